// End-to-end tests over every example scene: each scene in examples/scenes (found by listing
// the folder, so a new example is covered without touching this file) is generated,
// reported from the scene and from its database (byte-identical CSV, one row per face and
// light in scene order, lit fractions in [0, 1]), exported as OBJ and MTL (one group per
// face, its triangles adding up to the report's areas) and drawn from its `main` view
// (well-formed SVG per xmllint, naming only faces and lights of the scene).
//
// The pictures checked in beside the scenes (examples/<name>.svg, and the sun-hours map
// examples/<name>-sun-hours.svg of a scene with a sun path) are what the build target
// `example_pictures` makes: every scene has its picture and every picture its scene, and
// each picture is remade here by examples/render_examples.sh (the script that target runs)
// into a temporary folder and compared byte for byte with the one checked in.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "shadowgen/output/report.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/cli/cli_harness.h"
#include "tests/support/obj_text.h"

namespace shadowgen::test {
namespace {

const fs::path kExamples = fs::path(SHADOWGEN_EXAMPLES_DIR);

// How a checked-in picture is remade, for the messages.
constexpr const char* kRemake =
    "remake the pictures with `cmake --build --preset release --target example_pictures` "
    "(examples/README.md) and commit them";

// The example names (scene file stems), sorted.
std::vector<std::string> example_names() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(kExamples / "scenes", error)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") {
      names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The names (file stems) of the pictures checked in, examples/*.svg, sorted.
std::vector<std::string> picture_names() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(kExamples, error)) {
    if (entry.is_regular_file() && entry.path().extension() == ".svg") {
      names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The scene a picture is of: the picture's name, less "-sun-hours" for a sun-hours map,
// "-sun-hours-plan" for its plan and "-radiation" for a radiation map.
std::string scene_of(const std::string& picture) {
  for (const std::string map : {"-sun-hours-plan", "-sun-hours", "-radiation"}) {
    if (picture.ends_with(map)) return picture.substr(0, picture.size() - map.size());
  }
  return picture;
}

// The pictures checked in of the scene `name`, as file names, sorted.
std::vector<std::string> pictures_of(const std::string& name) {
  std::vector<std::string> files;
  for (const std::string& picture : picture_names()) {
    if (scene_of(picture) == name) files.push_back(picture + ".svg");
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The paths of an SVG picture: its `<path` elements.
std::size_t path_count(const std::string& svg) {
  std::size_t count = 0;
  for (std::size_t at = svg.find("<path"); at != std::string::npos;
       at = svg.find("<path", at + 1)) {
    ++count;
  }
  return count;
}

// Where two texts first differ: "byte B (line L)", both from 1; "" when they are the same.
std::string first_difference(const std::string& a, const std::string& b) {
  const auto [ia, ib] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  if (ia == a.end() && ib == b.end()) return "";
  const auto byte = static_cast<std::size_t>(ia - a.begin()) + 1;  // from 1, as cmp counts
  const auto line = 1 + std::count(a.begin(), ia, '\n');
  return "byte " + std::to_string(byte) + " (line " + std::to_string(line) + ")";
}

// A test's name for an example: its name with every character but letters and digits as '_'.
std::string test_name(const ::testing::TestParamInfo<std::string>& param) {
  std::string name = param.param;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

// Faces of an OBJ file: its `f` records.
std::size_t obj_face_count(const fs::path& path) {
  std::istringstream in(contents(path));
  std::size_t count = 0;
  for (std::string line; std::getline(in, line);) {
    const std::size_t start = line.find_first_not_of(" \t");
    if (start != std::string::npos && line.compare(start, 2, "f ") == 0) ++count;
  }
  return count;
}

// The face ids of a scene in scene order (polygons, then mesh faces "<mesh id>/<k>"), and
// its light ids.
struct SceneIds {
  std::vector<std::string> faces;
  std::vector<std::string> lights;
};

SceneIds scene_ids(const fs::path& scene_path) {
  const nlohmann::json scene = nlohmann::json::parse(contents(scene_path));
  SceneIds ids;
  for (const auto& polygon : scene.value("polygons", nlohmann::json::array())) {
    ids.faces.push_back(polygon.at("id").get<std::string>());
  }
  for (const auto& mesh : scene.value("meshes", nlohmann::json::array())) {
    const fs::path file = scene_path.parent_path() / mesh.at("file").get<std::string>();
    EXPECT_EQ(file.extension(), ".obj") << "count the faces of " << file << " here";
    const std::size_t faces = obj_face_count(file);
    EXPECT_GT(faces, 0u) << file;
    for (std::size_t k = 0; k < faces; ++k) {
      ids.faces.push_back(mesh.at("id").get<std::string>() + "/" + std::to_string(k));
    }
  }
  // A sun light is its instants, which only the sun's position tells.
  const Scene read = read_scene(scene_path).scene;
  for (const auto& light : scene.value("lights", nlohmann::json::array())) {
    const std::string id = light.at("id").get<std::string>();
    if (light.at("type") != "sun") {
      ids.lights.push_back(id);
      continue;
    }
    for (const Light& instant : read.lights) {
      if (instant.sun && instant.sun->sun_id == id) ids.lights.push_back(instant.id);
    }
  }
  return ids;
}

class ExampleCli : public CliFolderTest<::testing::TestWithParam<std::string>> {
 protected:
  ExampleCli() : CliFolderTest("shadowgen-examples") {}
};

TEST(ExampleScenes, TheFolderHoldsTheExamplesEachWithAMainViewAndItsPicture) {
  const std::vector<std::string> names = example_names();
  for (const char* expected :
       {"chairs", "courtyard", "garden", "house", "pergola", "roof", "room"}) {
    EXPECT_TRUE(std::find(names.begin(), names.end(), expected) != names.end()) << expected;
  }
  // The garden's sun path of 21 March also has its sun-hours map, that map as a plan, and
  // its radiation map.
  EXPECT_EQ(pictures_of("garden"),
            (std::vector<std::string>{"garden-radiation.svg", "garden-sun-hours-plan.svg",
                                      "garden-sun-hours.svg", "garden.svg"}));
  EXPECT_EQ(pictures_of("roof"), (std::vector<std::string>{"roof-sun-hours-plan.svg",
                                                           "roof-sun-hours.svg", "roof.svg"}));
  // A plan is seen from straight above: it has the site's north arrow and, being
  // orthographic, a scale bar; a perspective map has the arrow and no bar.
  for (const std::string name : {"garden", "roof"}) {
    const std::string plan = contents(kExamples / (name + "-sun-hours-plan.svg"));
    EXPECT_NE(plan.find("data-north-arrow"), std::string::npos) << name;
    EXPECT_NE(plan.find("data-scale-bar="), std::string::npos) << name;
    const std::string map = contents(kExamples / (name + "-sun-hours.svg"));
    EXPECT_NE(map.find("data-north-arrow"), std::string::npos) << name;
    EXPECT_EQ(map.find("data-scale-bar="), std::string::npos) << name;
  }
  // The radiation map's legend gives its bands in kWh/m² under its caption, and the site
  // gives it a north arrow.
  const std::string radiation = contents(kExamples / "garden-radiation.svg");
  EXPECT_NE(radiation.find("data-legend=\"radiation\""), std::string::npos);
  EXPECT_NE(radiation.find(">Irradiation, kWh/m²: march21</text>"), std::string::npos);
  EXPECT_NE(radiation.find(">0–0.5 kWh/m²</text>"), std::string::npos);
  EXPECT_NE(radiation.find("data-band=\"2–2.5 kWh/m²\""), std::string::npos);
  EXPECT_NE(radiation.find("data-north-arrow"), std::string::npos);
  for (const std::string& name : names) {
    const nlohmann::json scene =
        nlohmann::json::parse(contents(kExamples / "scenes" / (name + ".json")));
    EXPECT_EQ(scene.at("format"), "shadowgen-scene/1") << name;
    bool has_main = false;
    for (const auto& view : scene.value("views", nlohmann::json::array())) {
      has_main = has_main || view.at("id") == "main";
    }
    EXPECT_TRUE(has_main) << name << " has no view 'main'";
    // The picture the build target example_pictures makes from that view is checked in
    // (ExamplePicture below checks its bytes).
    const fs::path picture = kExamples / (name + ".svg");
    EXPECT_TRUE(fs::is_regular_file(picture)) << picture << " is missing: " << kRemake;
  }
  // ... and every picture checked in is one of a scene: no orphan.
  for (const std::string& name : picture_names()) {
    const fs::path picture = kExamples / (name + ".svg");
    const std::string scene = scene_of(name);
    EXPECT_TRUE(std::find(names.begin(), names.end(), scene) != names.end())
        << picture << " is the picture of no scene (no examples/scenes/" << scene
        << ".json): remove it, or add its scene and " << kRemake;
    EXPECT_NE(contents(picture).find("data-face="), std::string::npos) << picture;
    EXPECT_EQ(shell("xmllint --noout " + quoted(picture.string()) + " 2>/dev/null"), 0) << picture;
  }
}

class ExampleScript : public CliFolderTest<> {
 protected:
  ExampleScript() : CliFolderTest("shadowgen-example-script") {}
};

// examples/roof-year.sh: the roof's faces over every hour of 2026, as EnergyPlus reads a
// shading schedule: 8,760 rows, sunlit fractions from 0 to 1, nothing lit at night, the
// panels in the chimney's and their neighbours' shade at some hours and lit whole at
// others.
TEST_F(ExampleScript, TheRoofOverAYearIsAShadingScheduleOfEveryHour) {
  const fs::path out = dir_ / "roof-year.csv";
  const int code = shell("bash " + quoted((kExamples / "roof-year.sh").string()) + " " +
                         quoted(SHADOWGEN_EXECUTABLE) + " " + quoted(out.string()) + " >" +
                         quoted((dir_ / "run" / "out").string()) + " 2>" +
                         quoted((dir_ / "run" / "err").string()));
  ASSERT_EQ(code, 0) << contents(dir_ / "run" / "err");
  std::istringstream csv(contents(out));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = csv_fields(line);
  ASSERT_GE(header.size(), 3u);
  EXPECT_EQ(header.front(), "Surface Name");
  std::vector<std::size_t> panels;
  for (std::size_t i = 1; i + 1 < header.size(); ++i) {
    if (header[i].rfind("PANEL.", 0) == 0) panels.push_back(i);
  }
  ASSERT_EQ(panels.size(), 6u);
  std::size_t rows = 0, panel_partly = 0, panel_whole = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> fields = csv_fields(line);
    ASSERT_EQ(fields.size(), header.size()) << line;  // the trailing comma's empty field
    ++rows;
    if (rows == 1) {
      EXPECT_EQ(fields[0], " 01/01 01:00");
    }
    for (std::size_t i = 1; i + 1 < fields.size(); ++i) {
      const double fraction = std::stod(fields[i]);
      ASSERT_GE(fraction, 0.0) << line;
      ASSERT_LE(fraction, 1.0) << line;
      if (fields[0] == " 01/01 01:00") {
        EXPECT_EQ(fraction, 0.0) << header[i];
      }
    }
    for (const std::size_t i : panels) {
      const double fraction = std::stod(fields[i]);
      if (fraction > 0.0 && fraction < 1.0) ++panel_partly;
      if (fraction == 1.0) ++panel_whole;
    }
  }
  EXPECT_EQ(rows, 8760u);
  EXPECT_GT(panel_partly, 100u);
  EXPECT_GT(panel_whole, 1000u);
}

// The radiation map's weather, which the build writes (the target example_weather) rather
// than the repository keeping it: what examples/weather/clear_sky_epw.py writes with its
// defaults to standard output, byte for byte, a year of hourly rows, none of them measured.
TEST_F(ExampleScript, TheBuildsClearSkyWeatherFileIsTheScriptsOutput) {
  const fs::path built = fs::path(SHADOWGEN_EXAMPLE_WEATHER_DIR) / "greenwich-clear-sky.epw";
  ASSERT_TRUE(fs::is_regular_file(built))
      << built << " is missing: build the target example_weather";
  EXPECT_FALSE(fs::exists(kExamples / "weather" / "greenwich-clear-sky.epw"))
      << "the weather file is made by the build, not kept in examples/weather";
  const fs::path out = dir_ / "clear-sky.epw";
  const int code =
      shell("python3 " + quoted((kExamples / "weather" / "clear_sky_epw.py").string()) + " >" +
            quoted(out.string()) + " 2>" + quoted((dir_ / "err").string()));
  ASSERT_EQ(code, 0) << contents(dir_ / "err");
  const std::string fresh = contents(out);
  const std::string kept = contents(built);
  EXPECT_TRUE(fresh == kept) << built << " differs from the script's output at "
                             << first_difference(kept, fresh);
  EXPECT_EQ(std::count(kept.begin(), kept.end(), '\n'), 8 + 8760);
  EXPECT_NE(kept.find("COMMENTS 1,Synthetic"), std::string::npos);
}

class ExamplePicture : public CliFolderTest<::testing::TestWithParam<std::string>> {
 protected:
  ExamplePicture() : CliFolderTest("shadowgen-example-picture") {}
};

// A checked-in picture is, byte for byte, what examples/render_examples.sh (the script the
// build target example_pictures runs) makes from its scene with the shadowgen just built.
TEST_P(ExamplePicture, IsByteForByteAFreshRender) {
  const std::string name = GetParam();
  const std::string scene = scene_of(name);
  const fs::path checked_in = kExamples / (name + ".svg");
  ASSERT_TRUE(fs::is_regular_file(kExamples / "scenes" / (scene + ".json")))
      << checked_in << " is the picture of no scene";

  const fs::path fresh_folder = dir_ / "pictures";
  const fs::path out = dir_ / "run" / "out";
  const fs::path err = dir_ / "run" / "err";
  const std::string command = "bash " + quoted((kExamples / "render_examples.sh").string()) + " " +
                              quoted(SHADOWGEN_EXECUTABLE) + " --out " +
                              quoted(fresh_folder.string()) + " --databases " +
                              quoted((dir_ / "databases").string()) + " --weather " +
                              quoted(SHADOWGEN_EXAMPLE_WEATHER_DIR) + " " + quoted(scene) + " >" +
                              quoted(out.string()) + " 2>" + quoted(err.string());
  ASSERT_EQ(shell(command), 0) << command << "\n" << contents(out) << contents(err);
  EXPECT_EQ(contents(err), "");
  const fs::path fresh_path = fresh_folder / (name + ".svg");
  ASSERT_TRUE(fs::is_regular_file(fresh_path)) << command;
  // The script makes only the pictures of the scene asked for.
  EXPECT_EQ(sorted_names(fresh_folder, {}), pictures_of(scene));

  const std::string fresh = contents(fresh_path);
  const std::string kept = contents(checked_in);
  ASSERT_FALSE(fresh.empty());
  EXPECT_TRUE(kept == fresh) << "examples/" << name
                             << ".svg differs from a fresh render of examples/scenes/" << scene
                             << ".json (" << path_count(kept) << " paths checked in, "
                             << path_count(fresh) << " fresh; first difference at "
                             << first_difference(kept, fresh) << "; the fresh one is " << fresh_path
                             << "): " << kRemake;
  std::printf("%s.svg: %zu bytes, %zu paths, %s\n", name.c_str(), kept.size(), path_count(kept),
              kept == fresh ? "same as a fresh render" : "NOT a fresh render");
}

INSTANTIATE_TEST_SUITE_P(Examples, ExamplePicture, ::testing::ValuesIn(picture_names()), test_name);

TEST_P(ExampleCli, GenerateReportExportRender) {
  const std::string name = GetParam();
  const fs::path scene = kExamples / "scenes" / (name + ".json");
  const SceneIds ids = scene_ids(scene);
  ASSERT_FALSE(ids.faces.empty());
  ASSERT_FALSE(ids.lights.empty());

  // generate: a clean example reads without warnings. Sun paths keep their instants' lit
  // polygons, which export and render draw.
  const fs::path db = dir_ / (name + ".shadowed.json");
  const Outcome generated = run({"generate", scene.string(), "-o", db.string(), "--keep-instants"});
  ASSERT_EQ(generated.code, 0) << generated.err;
  EXPECT_EQ(generated.out, "");
  EXPECT_EQ(generated.err, "");
  ASSERT_TRUE(fs::is_regular_file(db));
  EXPECT_EQ(nlohmann::json::parse(contents(db)).at("format"), "shadowgen-shadowed/2");

  // report: the same CSV, byte for byte, from the scene and from the database.
  const Outcome from_db = run({"report", db.string(), "--format", "csv"});
  const Outcome from_scene = run({"report", scene.string()});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  ASSERT_EQ(from_scene.code, 0) << from_scene.err;
  EXPECT_EQ(from_db.err, "");
  EXPECT_EQ(from_scene.out, from_db.out);
  // ... and the library's own report of the same scene, generated in this process.
  EXPECT_EQ(from_db.out, report_csv(generate_shadows(read_scene(scene).scene).shadowed));

  // One row per (face, light), faces in scene order, lights in scene order.
  const std::vector<ReportRow> rows = parse_report(from_db.out);
  ASSERT_EQ(rows.size(), ids.faces.size() * ids.lights.size());
  std::map<std::string, bool> partly_shadowed;  // by light: some face is lit in part only
  for (std::size_t f = 0; f < ids.faces.size(); ++f) {
    for (std::size_t l = 0; l < ids.lights.size(); ++l) {
      const ReportRow& row = rows[f * ids.lights.size() + l];
      EXPECT_EQ(row.face, ids.faces[f]);
      EXPECT_EQ(row.light, ids.lights[l]);
      EXPECT_GT(row.area, 0.0) << row.face;
      EXPECT_GE(row.lit_area, 0.0) << row.face << ", " << row.light;
      EXPECT_LE(row.lit_area, row.area * (1.0 + 1e-12)) << row.face << ", " << row.light;
      EXPECT_GE(row.lit_fraction, 0.0) << row.face << ", " << row.light;
      EXPECT_LE(row.lit_fraction, 1.0) << row.face << ", " << row.light;
      if (row.area > 0.0) {
        EXPECT_DOUBLE_EQ(row.lit_fraction, row.lit_area / row.area) << row.face;
      }
      if (row.lit_fraction > 0.0 && row.lit_fraction < 1.0) partly_shadowed[row.light] = true;
    }
  }
  // An example shows shadows: every light leaves some face partly in shadow.
  for (const std::string& light : ids.lights) {
    EXPECT_TRUE(partly_shadowed[light]) << light << " casts no shadow on any face";
  }

  // export: OBJ and MTL, a group per face in scene order, every material defined, and
  // each group's triangles adding up to the report's area and lit areas.
  const fs::path obj_path = dir_ / (name + ".obj");
  const fs::path mtl_path = dir_ / (name + ".mtl");
  const Outcome exported = run({"export", db.string(), "--obj", obj_path.string()});
  ASSERT_EQ(exported.code, 0) << exported.err;
  EXPECT_EQ(exported.err, "");
  ASSERT_TRUE(fs::is_regular_file(obj_path));
  ASSERT_TRUE(fs::is_regular_file(mtl_path));
  const ObjText obj = parse_obj(contents(obj_path));
  EXPECT_TRUE(obj.errors.empty()) << obj.errors.front();
  EXPECT_EQ(obj.mtllib, mtl_path.filename().string());
  std::vector<std::string> groups;
  for (const auto& group : obj.groups) groups.push_back(group.name);
  EXPECT_EQ(groups, ids.faces);
  const MtlText mtl = parse_mtl(contents(mtl_path));
  EXPECT_TRUE(mtl.errors.empty()) << mtl.errors.front();
  double worst = 0.0;
  for (const auto& group : obj.groups) {
    const std::map<std::string, double> areas = material_areas(group);
    double total = 0.0;
    std::map<std::string, double> lit;  // by light
    for (const auto& [material, area] : areas) {
      EXPECT_EQ(mtl.kd.count(material), 1u) << material;
      total += area;
      if (material == "shadow") continue;
      std::istringstream lights(material);
      for (std::string light; std::getline(lights, light, '+');) lit[light] += area;
    }
    for (const ReportRow& row : rows) {
      if (row.face != group.name) continue;
      const double area_error = relative_error(total, row.area);
      const double lit_error = relative_error(lit[row.light], row.lit_area);
      EXPECT_LE(area_error, 1e-9) << row.face << ": " << total << " vs " << row.area;
      EXPECT_LE(lit_error, 1e-9) << row.face << ", " << row.light << ": " << lit[row.light]
                                 << " vs " << row.lit_area;
      worst = std::max({worst, area_error, lit_error});
    }
  }
  std::printf("%s: %zu faces, %zu lights, OBJ areas within %.3g of the report\n", name.c_str(),
              ids.faces.size(), ids.lights.size(), worst);

  // render: the `main` view, a well-formed SVG that names only the scene's faces and lights.
  const fs::path svg = dir_ / (name + ".svg");
  const Outcome rendered =
      run({"render", "--pieces", db.string(), "--view", "main", "--svg", svg.string()});
  ASSERT_EQ(rendered.code, 0) << rendered.err;
  EXPECT_EQ(rendered.out, "");
  EXPECT_EQ(rendered.err, "");
  ASSERT_TRUE(fs::is_regular_file(svg));
  ExpectWellFormedXml(svg, dir_ / "run" / "xmllint");
  const std::string picture = contents(svg);
  const std::set<std::string> faces(ids.faces.begin(), ids.faces.end());
  std::set<std::string> light_sets(ids.lights.begin(), ids.lights.end());
  light_sets.insert("shadow");
  const std::regex piece(R"re(data-face="([^"]*)" data-lights="([^"]*)")re");
  std::size_t pieces = 0;
  std::set<std::string> seen;
  for (auto it = std::sregex_iterator(picture.begin(), picture.end(), piece);
       it != std::sregex_iterator(); ++it) {
    ++pieces;
    EXPECT_EQ(faces.count((*it)[1]), 1u) << (*it)[1];
    seen.insert((*it)[1]);
    std::istringstream lights((*it)[2]);
    for (std::string light; std::getline(lights, light, '+');) {
      EXPECT_EQ(light_sets.count(light), 1u) << light;
    }
  }
  EXPECT_GT(pieces, 0u);
  EXPECT_GE(seen.size(), 2u);  // the view shows more than one face
}

// compare finishes on every example, its exact row first and without error, every sampled
// row with an error no larger than a lit fraction can be wrong by.
// With its first view, if it has one, the view methods' rows follow, each with a share from
// 0 to 1.
TEST_P(ExampleCli, CompareFinishesWithAnExactRowWithoutError) {
  const fs::path scene = kExamples / "scenes" / (GetParam() + ".json");
  const nlohmann::json json = nlohmann::json::parse(contents(scene));
  const nlohmann::json views = json.value("views", nlohmann::json::array());
  std::vector<std::string> args{
      "compare",  scene.string(), "--methods", "rays:4,shadow-map:128:samples=4",
      "--format", "csv",          "--quiet"};
  if (!views.empty()) {
    args.insert(args.end(), {"--view", views[0].at("id").get<std::string>(), "--width", "64",
                             "--height", "48", "--view-methods", "volumes,shadow-map:512"});
  }
  const Outcome outcome = run(args);
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  std::istringstream in(outcome.out);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line) && !line.empty()) rows.push_back(csv_fields(line));
  std::vector<std::vector<std::string>> view_rows;
  if (std::getline(in, line)) {
    EXPECT_EQ(line, "view_method,resolution,seconds,differing_share,pairs,pareto");
    while (std::getline(in, line)) view_rows.push_back(csv_fields(line));
  }
  ASSERT_EQ(view_rows.size(), views.empty() ? 0u : 2u) << outcome.out;
  for (const std::vector<std::string>& row : view_rows) {
    ASSERT_EQ(row.size(), 6u) << outcome.out;
    const double share = std::stod(row[3]);
    const std::string method = row[1].empty() ? row[0] : row[0] + " " + row[1];
    std::printf("[ figures  ] %s, view %s: %s differs on %.4g%% of %s pairs, %s s\n",
                GetParam().c_str(), views[0].at("id").get<std::string>().c_str(), method.c_str(),
                100.0 * share, row[4].c_str(), row[2].c_str());
    EXPECT_GE(share, 0.0);
    EXPECT_LE(share, 1.0);
  }
  if (!view_rows.empty()) {
    EXPECT_EQ(view_rows[0][0], "volumes");
    EXPECT_EQ(view_rows[1][0] + ":" + view_rows[1][1], "shadow-map:512");
  }
  ASSERT_EQ(rows.size(), 3u) << outcome.out;
  EXPECT_EQ(rows[0][0], "exact");
  EXPECT_EQ(rows[0][4], "0");
  EXPECT_EQ(rows[0][5], "0");
  EXPECT_EQ(rows[0][8], "1");  // nothing is more accurate
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const double mean = std::stod(rows[r][4]), max = std::stod(rows[r][5]);
    EXPECT_GE(mean, 0.0);
    EXPECT_LE(mean, max);
    EXPECT_LE(max, 1.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleCli, ::testing::ValuesIn(example_names()), test_name);

}  // namespace
}  // namespace shadowgen::test
