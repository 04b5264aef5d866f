// End-to-end tests of `shadowgen export --obj`: the built executable is run on the
// courtyard example, from a database and from the scene, and the OBJ it writes is read back
// (tests/support/obj_text.h) and compared with `shadowgen report`'s CSV; failures must exit
// 1 with one message and leave neither the OBJ nor the MTL behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"
#include "tests/cli/cli_scenes.h"
#include "tests/support/gltf_file.h"
#include "tests/support/obj_text.h"

namespace shadowgen::test {
namespace {

const fs::path kCourtyard = fs::path(SHADOWGEN_EXAMPLES_DIR) / "scenes" / "courtyard.json";

class ExportCli : public CliFolderTest<> {
 protected:
  ExportCli() : CliFolderTest("shadowgen-export") {}
};

// The lights of a material, from its name ("shadow", "sun", "sun+lamp").
std::vector<std::string> lights_of(const std::string& material) {
  std::vector<std::string> lights;
  if (material == "shadow") return lights;
  std::istringstream in(material);
  std::string id;
  while (std::getline(in, id, '+')) lights.push_back(id);
  return lights;
}

// Per face group: all triangles add up to the report's area, and the materials holding a
// light to its lit_area, within `tolerance` relative. Returns the worst error seen.
double ExpectObjMatchesReport(const std::string& obj_text, const std::string& csv,
                              double tolerance) {
  const ObjText obj = parse_obj(obj_text);
  EXPECT_TRUE(obj.errors.empty()) << obj.errors.front();
  const std::vector<ReportRow> rows = parse_report(csv);
  double worst = 0.0;
  std::size_t checked = 0;
  for (const ReportRow& row : rows) {
    const auto group = std::find_if(obj.groups.begin(), obj.groups.end(),
                                    [&row](const auto& g) { return g.name == row.face; });
    if (group == obj.groups.end()) {
      ADD_FAILURE() << "no group " << row.face;
      continue;
    }
    const std::map<std::string, double> areas = material_areas(*group);
    double total = 0.0, lit = 0.0;
    for (const auto& [material, a] : areas) {
      total += a;
      const std::vector<std::string> lights = lights_of(material);
      if (std::find(lights.begin(), lights.end(), row.light) != lights.end()) lit += a;
    }
    const double area_error = relative_error(total, row.area);
    const double lit_error =
        row.lit_area > 0.0 ? relative_error(lit, row.lit_area) : lit / std::max(row.area, 1.0);
    EXPECT_LE(area_error, tolerance) << row.face << ": " << total << " vs " << row.area;
    EXPECT_LE(lit_error, tolerance)
        << row.face << ", " << row.light << ": " << lit << " vs " << row.lit_area;
    worst = std::max({worst, area_error, lit_error});
    ++checked;
  }
  EXPECT_GT(checked, 0u);
  return worst;
}

// The OBJ without its mtllib line, which names the MTL file.
std::string without_mtllib(const std::string& obj) {
  std::istringstream in(obj);
  std::string line, out;
  while (std::getline(in, line)) {
    if (line.rfind("mtllib ", 0) != 0) out += line + '\n';
  }
  return out;
}

TEST_F(ExportCli, CourtyardFromDatabaseAndFromSceneMatchTheReport) {
  const fs::path db = dir_ / "courtyard.shadowed.json";
  ASSERT_EQ(run({"generate", kCourtyard.string(), "-o", db.string()}).code, 0);

  const Outcome from_db = run({"export", db.string(), "--obj", (dir_ / "db.obj").string()});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.out, "");
  EXPECT_EQ(from_db.err, "");
  const Outcome from_scene = run(
      {"export", kCourtyard.string(), "--obj", (dir_ / "scene.obj").string(), "--threads", "2"});
  ASSERT_EQ(from_scene.code, 0) << from_scene.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"courtyard.shadowed.json", "db.mtl", "db.obj",
                                               "scene.mtl", "scene.obj"}));

  const std::string obj = contents(dir_ / "db.obj");
  EXPECT_EQ(parse_obj(obj).mtllib, "db.mtl");
  EXPECT_EQ(parse_obj(contents(dir_ / "scene.obj")).mtllib, "scene.mtl");
  EXPECT_EQ(without_mtllib(obj), without_mtllib(contents(dir_ / "scene.obj")));
  EXPECT_EQ(contents(dir_ / "db.mtl"), contents(dir_ / "scene.mtl"));

  // Every face is a group, in scene order.
  std::vector<std::string> groups;
  for (const auto& g : parse_obj(obj).groups) groups.push_back(g.name);
  EXPECT_EQ(groups, (std::vector<std::string>{"ground", "wall-south", "canopy"}));

  // Every material the OBJ uses is defined in the MTL, shadow darker than any lit set.
  const MtlText mtl = parse_mtl(contents(dir_ / "db.mtl"));
  EXPECT_TRUE(mtl.errors.empty());
  ASSERT_EQ(mtl.kd.count("shadow"), 1u);
  for (const auto& g : parse_obj(obj).groups) {
    for (const auto& t : g.triangles) EXPECT_EQ(mtl.kd.count(t.material), 1u) << t.material;
  }
  for (const auto& [name, kd] : mtl.kd) {
    if (name != "shadow") {
      EXPECT_GT(kd[0], mtl.kd.at("shadow")[0]) << name;
    }
  }

  const Outcome report = run({"report", db.string()});
  ASSERT_EQ(report.code, 0) << report.err;
  const double worst = ExpectObjMatchesReport(obj, report.out, 1e-9);
  std::printf("courtyard, two lights: worst relative area error %.3g\n", worst);
}

// --by-light: per face its whole group, then one layer per light reaching it, whose
// triangles add up to the report's lit area; the same from the scene and the database.
TEST_F(ExportCli, ByLightWritesALayerPerLightMatchingTheReport) {
  const fs::path db = dir_ / "courtyard.shadowed.json";
  ASSERT_EQ(run({"generate", kCourtyard.string(), "-o", db.string()}).code, 0);
  const Outcome r =
      run({"export", db.string(), "--obj", (dir_ / "layers.obj").string(), "--by-light"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string obj_text = contents(dir_ / "layers.obj");
  const ObjText obj = parse_obj(obj_text);
  ASSERT_TRUE(obj.errors.empty()) << obj.errors.front();
  std::vector<std::string> groups;
  for (const auto& g : obj.groups) groups.push_back(g.name);
  EXPECT_EQ(groups,
            (std::vector<std::string>{"ground", "ground@sun", "ground@lamp", "wall-south",
                                      "wall-south@sun", "canopy", "canopy@sun", "canopy@lamp"}));
  const MtlText mtl = parse_mtl(contents(dir_ / "layers.mtl"));
  EXPECT_EQ(mtl.order, (std::vector<std::string>{"shadow", "sun", "lamp"}));

  const Outcome report = run({"report", db.string()});
  ASSERT_EQ(report.code, 0) << report.err;
  std::size_t checked = 0;
  for (const ReportRow& row : parse_report(report.out)) {
    const auto whole = std::find_if(obj.groups.begin(), obj.groups.end(),
                                    [&row](const auto& g) { return g.name == row.face; });
    ASSERT_NE(whole, obj.groups.end()) << row.face;
    EXPECT_LE(relative_error(material_areas(*whole).at("shadow"), row.area), 1e-9) << row.face;
    const auto layer = std::find_if(obj.groups.begin(), obj.groups.end(), [&row](const auto& g) {
      return g.name == row.face + "@" + row.light;
    });
    if (row.lit_area == 0.0) {
      EXPECT_EQ(layer, obj.groups.end()) << row.face << "@" << row.light;
      continue;
    }
    ASSERT_NE(layer, obj.groups.end()) << row.face << "@" << row.light;
    EXPECT_LE(relative_error(material_areas(*layer).at(row.light), row.lit_area), 1e-9);
    ++checked;
  }
  EXPECT_EQ(checked, 5u);

  const Outcome from_scene =
      run({"export", kCourtyard.string(), "--obj", (dir_ / "scene.obj").string(), "--by-light"});
  ASSERT_EQ(from_scene.code, 0) << from_scene.err;
  EXPECT_EQ(without_mtllib(obj_text), without_mtllib(contents(dir_ / "scene.obj")));
  // A layer per light and a sun-hours map are two exports, not one.
  EXPECT_EQ(run({"export", db.string(), "--obj", (dir_ / "x.obj").string(), "--by-light",
                 "--sun-hours", "day"})
                .code,
            2);
  EXPECT_FALSE(fs::exists(dir_ / "x.obj"));
}

// An OBJ whose name has a space: mtllib separates file names by spaces, so the MTL is
// named with the escaped stem and mtllib names it as it is (it once read "mtllib my
// scene.mtl", two files that do not exist).
TEST_F(ExportCli, AnObjNameWithASpaceGetsAnMtlThatMtllibNamesWhole) {
  const Outcome r = run({"export", kCourtyard.string(), "--obj", (dir_ / "my scene.obj").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"my scene.obj", "my%20scene.mtl"}));
  const std::string obj = contents(dir_ / "my scene.obj");
  EXPECT_NE(obj.find("\nmtllib my%20scene.mtl\n"), std::string::npos) << obj.substr(0, 200);
  EXPECT_TRUE(parse_mtl(contents(dir_ / "my%20scene.mtl")).errors.empty());
}

TEST_F(ExportCli, SingleLightLitMaterialAreaIsTheReportsLitArea) {
  nlohmann::json scene = nlohmann::json::parse(contents(kCourtyard));
  scene["lights"].erase(1);  // keep the sun only
  ASSERT_EQ(scene["lights"].size(), 1u);
  const fs::path path = write("sun.json", scene.dump(2));
  const Outcome exported = run({"export", path.string(), "--obj", (dir_ / "sun.obj").string()});
  ASSERT_EQ(exported.code, 0) << exported.err;
  const Outcome report = run({"report", path.string()});
  ASSERT_EQ(report.code, 0) << report.err;

  const ObjText obj = parse_obj(contents(dir_ / "sun.obj"));
  const std::vector<ReportRow> rows = parse_report(report.out);
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(obj.groups.size(), 3u);
  double worst = 0.0;
  for (std::size_t f = 0; f < rows.size(); ++f) {
    EXPECT_EQ(obj.groups[f].name, rows[f].face);
    std::map<std::string, double> areas = material_areas(obj.groups[f]);
    for (const auto& [material, a] : areas) {
      EXPECT_TRUE(material == "sun" || material == "shadow") << material;
    }
    const double lit_error = relative_error(areas["sun"], rows[f].lit_area);
    const double area_error = relative_error(areas["sun"] + areas["shadow"], rows[f].area);
    EXPECT_LE(lit_error, 1e-9) << rows[f].face;
    EXPECT_LE(area_error, 1e-9) << rows[f].face;
    worst = std::max({worst, lit_error, area_error});
  }
  // The sun lights part of the ground and not all of it: both materials there.
  EXPECT_GT(material_areas(obj.groups[0])["shadow"], 0.0);
  EXPECT_GT(material_areas(obj.groups[0])["sun"], 0.0);
  std::printf("courtyard, sun only: worst relative area error %.3g\n", worst);
}

// --lights sun on the two-light courtyard, from the scene or from its database, is the
// scene with the sun alone: the same OBJ and MTL byte for byte (the lamp is not generated
// from the scene, and dropped from the database).
TEST_F(ExportCli, LightsPicksLightsAsIfTheSceneHeldNoOther) {
  nlohmann::json scene = nlohmann::json::parse(contents(kCourtyard));
  scene["lights"].erase(1);
  const fs::path sun_only = write("sun.json", scene.dump(2));
  ASSERT_EQ(run({"export", sun_only.string(), "--obj", (dir_ / "alone.obj").string()}).code, 0);
  const fs::path db = dir_ / "courtyard.shadowed.json";
  ASSERT_EQ(run({"generate", kCourtyard.string(), "-o", db.string()}).code, 0);
  for (const fs::path& input : {kCourtyard, db}) {
    const Outcome r =
        run({"export", input.string(), "--lights", "sun", "--obj", (dir_ / "picked.obj").string()});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(without_mtllib(contents(dir_ / "picked.obj")),
              without_mtllib(contents(dir_ / "alone.obj")))
        << input;
    EXPECT_EQ(contents(dir_ / "picked.mtl"), contents(dir_ / "alone.mtl")) << input;
  }

  const Outcome unknown =
      run({"export", db.string(), "--lights", "sun,moon", "--obj", (dir_ / "moon.obj").string()});
  EXPECT_EQ(unknown.code, 1);
  EXPECT_EQ(unknown.err, "shadowgen: " + db.string() +
                             ": --lights names 'moon', which is not a light of it (its lights: "
                             "'sun', 'lamp')\n");
  EXPECT_FALSE(fs::exists(dir_ / "moon.obj"));
  EXPECT_FALSE(fs::exists(dir_ / "moon.mtl"));
}

TEST_F(ExportCli, BadInputExitsOneWithAMessageAndLeavesNothing) {
  const Outcome missing =
      run({"export", (dir_ / "missing.json").string(), "--obj", (dir_ / "out.obj").string()});
  EXPECT_EQ(missing.code, 1);
  EXPECT_EQ(missing.err.rfind("shadowgen: ", 0), 0u) << missing.err;
  EXPECT_NE(missing.err.find("missing.json"), std::string::npos) << missing.err;
  EXPECT_EQ(files(), std::vector<std::string>{});

  const fs::path broken = write("broken.json", kStubScene);
  const Outcome bad = run({"export", broken.string(), "--obj", (dir_ / "out.obj").string()});
  EXPECT_EQ(bad.code, 1);
  EXPECT_EQ(bad.err.rfind("shadowgen: ", 0), 0u) << bad.err;
  EXPECT_NE(bad.err.find("broken.json"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("stub"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_EQ(bad.out, "");

  const fs::path bad_db = write("bad-db.json", R"({"format": "shadowgen-shadowed/1"})");
  const Outcome db = run({"export", bad_db.string(), "--obj", (dir_ / "out.obj").string()});
  EXPECT_EQ(db.code, 1);
  EXPECT_EQ(db.err.rfind("shadowgen: " + bad_db.string() + ": ", 0), 0u) << db.err;

  const fs::path other = write("other.json", R"({"format": "something-else/3"})");
  const Outcome unknown = run({"export", other.string(), "--obj", (dir_ / "out.obj").string()});
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.err.find("something-else/3"), std::string::npos) << unknown.err;

  EXPECT_EQ(files(), (std::vector<std::string>{"bad-db.json", "broken.json", "other.json"}));
}

TEST_F(ExportCli, UnwritableOutputLeavesNeitherFile) {
  // No such folder: the MTL cannot be written.
  const Outcome nowhere =
      run({"export", kCourtyard.string(), "--obj", (dir_ / "no" / "such" / "out.obj").string()});
  EXPECT_EQ(nowhere.code, 1);
  EXPECT_NE(nowhere.err.find("out.mtl"), std::string::npos) << nowhere.err;

  // The OBJ's path is a folder: the MTL is written first, then removed when the OBJ fails.
  fs::create_directories(dir_ / "out.obj");
  const Outcome blocked =
      run({"export", kCourtyard.string(), "--obj", (dir_ / "out.obj").string()});
  EXPECT_EQ(blocked.code, 1);
  EXPECT_NE(blocked.err.find("out.obj"), std::string::npos) << blocked.err;
  EXPECT_EQ(files(), std::vector<std::string>{"out.obj"});
  EXPECT_TRUE(fs::is_directory(dir_ / "out.obj"));
  EXPECT_TRUE(fs::is_empty(dir_ / "out.obj"));

  // An OBJ name whose MTL would be the OBJ itself.
  const Outcome same = run({"export", kCourtyard.string(), "--obj", (dir_ / "x.mtl").string()});
  EXPECT_EQ(same.code, 1);
  EXPECT_NE(same.err.find("x.mtl"), std::string::npos) << same.err;
  EXPECT_EQ(files(), std::vector<std::string>{"out.obj"});
}

TEST_F(ExportCli, AFailedRunLeavesExistingOutputsAlone) {
  const fs::path obj = write("out.obj", "old obj");
  const fs::path mtl = write("out.mtl", "old mtl");
  const fs::path broken = write("broken.json", R"({"format": "shadowgen-scene/1", "polygons": [)");
  EXPECT_EQ(run({"export", broken.string(), "--obj", obj.string()}).code, 1);
  EXPECT_EQ(contents(obj), "old obj");
  EXPECT_EQ(contents(mtl), "old mtl");
}

TEST_F(ExportCli, WarningsAndStrict) {
  const fs::path scene = write("bent.json", kBentScene);
  const Outcome loud = run({"export", scene.string(), "--obj", (dir_ / "a.obj").string()});
  EXPECT_EQ(loud.code, 0) << loud.err;
  EXPECT_NE(loud.err.find("warning"), std::string::npos) << loud.err;
  const Outcome quiet =
      run({"export", scene.string(), "--obj", (dir_ / "b.obj").string(), "--quiet"});
  EXPECT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(without_mtllib(contents(dir_ / "a.obj")), without_mtllib(contents(dir_ / "b.obj")));
  // The bent square is two triangles, each with its own normal, all lit.
  const ObjText obj = parse_obj(contents(dir_ / "a.obj"));
  EXPECT_EQ(obj.normals.size(), 2u);
  ASSERT_EQ(obj.groups.size(), 1u);
  EXPECT_EQ(material_areas(obj.groups[0]).count("sun"), 1u);

  const Outcome strict =
      run({"export", scene.string(), "--obj", (dir_ / "c.obj").string(), "--strict"});
  EXPECT_EQ(strict.code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "c.obj"));
  EXPECT_FALSE(fs::exists(dir_ / "c.mtl"));
}

// Per face, from a glTF export's bytes: the area of its pieces' triangles, all of them
// ("") and those of the materials whose light sets hold each light.
std::map<std::string, std::map<std::string, double>> gltf_face_areas(GltfFile& file) {
  std::map<std::string, std::map<std::string, double>> areas;
  const nlohmann::json& ids = file.json["scenes"][0]["extras"]["faces"]["id"];
  for (std::size_t m = 0; m < file.json["meshes"].size(); ++m) {
    const nlohmann::json& mesh = file.json["meshes"][m];
    const nlohmann::json& material =
        file.json["materials"][mesh["primitives"][0]["material"].get<std::size_t>()];
    const nlohmann::json& pieces = mesh["extras"]["pieces"];
    const std::vector<GltfTriangle> triangles = mesh_triangles(file, m);
    for (std::size_t k = 0; k < pieces["face"].size(); ++k) {
      const std::size_t end = k + 1 < pieces["face"].size()
                                  ? pieces["first_triangle"][k + 1].get<std::size_t>()
                                  : triangles.size();
      double area = 0.0;
      for (std::size_t t = pieces["first_triangle"][k]; t < end; ++t) {
        area += triangle_area(triangles[t]);
      }
      const std::string face = ids[pieces["face"][k].get<std::size_t>()];
      areas[face][""] += area;
      for (const auto& light : material["extras"]["lights"]) areas[face][light] += area;
    }
  }
  return areas;
}

// --gltf: per face, its pieces' triangles add up to the report's area, those of the light
// sets holding a light to its lit area, within float32's rounding of positions around the
// courtyard's centre; the same from the scene and from the database, binary or JSON.
TEST_F(ExportCli, GltfFacesAndLitAreasMatchTheReport) {
  const fs::path db = dir_ / "courtyard.shadowed.json";
  ASSERT_EQ(run({"generate", kCourtyard.string(), "-o", db.string()}).code, 0);
  const Outcome report = run({"report", db.string()});
  ASSERT_EQ(report.code, 0) << report.err;
  const std::vector<ReportRow> rows = parse_report(report.out);
  ASSERT_EQ(rows.size(), 6u);
  for (const std::string name : {"db.glb", "db.gltf", "scene.glb"}) {
    const fs::path input = name.rfind("db", 0) == 0 ? db : kCourtyard;
    const Outcome exported = run({"export", input.string(), "--gltf", (dir_ / name).string()});
    ASSERT_EQ(exported.code, 0) << exported.err;
    EXPECT_EQ(exported.out, "");
    EXPECT_EQ(exported.err, "");
    keep_file_for_validator(dir_ / name);
    GltfFile file = parse_gltf(contents(dir_ / name));
    ASSERT_TRUE(file.errors.empty()) << file.errors.front();
    EXPECT_EQ(file.json["scenes"][0]["extras"]["faces"]["id"],
              nlohmann::json({"ground", "wall-south", "canopy"}));
    auto areas = gltf_face_areas(file);
    double worst = 0.0;
    for (const ReportRow& row : rows) {
      const double area_error = relative_error(areas[row.face][""], row.area);
      const double lit_error = std::abs(areas[row.face][row.light] - row.lit_area) / row.area;
      EXPECT_LE(area_error, 1e-6) << name << ", " << row.face;
      EXPECT_LE(lit_error, 1e-6) << name << ", " << row.face << ", " << row.light;
      worst = std::max({worst, area_error, lit_error});
    }
    std::printf("courtyard %s: worst relative area error %.3g\n", name.c_str(), worst);
  }
  EXPECT_EQ(contents(dir_ / "db.glb"), contents(dir_ / "scene.glb"));
  EXPECT_EQ(contents(dir_ / "db.glb").substr(0, 4), "glTF");
  EXPECT_EQ(contents(dir_ / "db.gltf").substr(0, 1), "{");
}

// A scene naming the exported file in its meshes reads the courtyard back: the glTF reader
// turns glTF's +y up back to +z up, so the faces stand where they stood, over the box
// (0, 0, 0)–(20, 20, 3), and their area is the courtyard's, 447 (float32 positions around
// the centre (10, 10, 1.5): within 1e-6).
TEST_F(ExportCli, GltfReadBackAsAMeshGivesTheSameFacesAndArea) {
  for (const std::string name : {"c.glb", "c.gltf"}) {
    const fs::path model = dir_ / name;
    ASSERT_EQ(run({"export", kCourtyard.string(), "-o", model.string()}).code, 0);
    const fs::path scene = write("again.json", R"({"format": "shadowgen-scene/1",
        "meshes": [{"id": "m", "file": ")" + name + R"("}],
        "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]})");
    const fs::path db = dir_ / "again.shadowed.json";
    const Outcome generated = run({"generate", scene.string(), "-o", db.string(), "-q"});
    ASSERT_EQ(generated.code, 0) << generated.err;
    const Outcome report = run({"report", db.string()});
    ASSERT_EQ(report.code, 0) << report.err;
    double area = 0.0;
    for (const ReportRow& row : parse_report(report.out)) area += row.area;
    EXPECT_LE(relative_error(area, 447.0), 1e-6) << name << ": " << area;
    glm::dvec3 least(INFINITY), most(-INFINITY);
    const nlohmann::json database = nlohmann::json::parse(contents(db));
    for (const auto& face : database.at("faces")) {
      for (const auto& part : face.at("parts")) {
        for (const auto& p : part.at("outer")) {
          const glm::dvec3 v(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
          least = glm::min(least, v);
          most = glm::max(most, v);
        }
      }
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(least[c], 0.0, 1e-5) << name << ", axis " << c;
      EXPECT_NEAR(most[c], glm::dvec3(20, 20, 3)[c], 1e-5) << name << ", axis " << c;
    }
  }
}

TEST_F(ExportCli, GltfUsageErrorsAndUnwritableFilesLeaveNothing) {
  const std::string glb = (dir_ / "out.glb").string();
  const Outcome txt = run({"export", kCourtyard.string(), "--gltf", (dir_ / "out.txt").string()});
  EXPECT_EQ(txt.code, 2);
  EXPECT_EQ(txt.err, "shadowgen: --gltf " + (dir_ / "out.txt").string() +
                         ": a glTF file's name ends in \".glb\" (binary) or \".gltf\" (JSON)\n"
                         "Run with --help for more information.\n");
  const Outcome layers = run({"export", kCourtyard.string(), "-o", glb, "--by-light"});
  EXPECT_EQ(layers.code, 2);
  EXPECT_EQ(layers.err.rfind("shadowgen: --by-light writes OBJ layers; a glTF file takes the "
                             "light sets or --sun-hours\n",
                             0),
            0u)
      << layers.err;
  const Outcome twice = run({"export", kCourtyard.string(), "-o", glb, "--gltf", glb});
  EXPECT_EQ(twice.code, 2);
  EXPECT_EQ(twice.err.rfind("shadowgen: --gltf " + glb + " and -o " + glb +
                                " both name the binary glTF file; give one\n",
                            0),
            0u)
      << twice.err;
  const Outcome nowhere =
      run({"export", kCourtyard.string(), "-o", (dir_ / "no" / "out.glb").string()});
  EXPECT_EQ(nowhere.code, 1);
  EXPECT_NE(nowhere.err.find("out.glb"), std::string::npos) << nowhere.err;
  EXPECT_EQ(files(), std::vector<std::string>{});
}

// -o names an OBJ, a binary glTF and a JSON glTF at once: one generation, three models of
// the same regions.
TEST_F(ExportCli, MinusONamesAnObjAndGltfFilesAtOnce) {
  const Outcome all = run({"export", kCourtyard.string(), "-o", (dir_ / "a.obj").string(), "-o",
                           (dir_ / "a.glb").string(), "--gltf", (dir_ / "b.gltf").string()});
  ASSERT_EQ(all.code, 0) << all.err;
  EXPECT_EQ(files(), (std::vector<std::string>{"a.glb", "a.mtl", "a.obj", "b.gltf"}));
  ASSERT_EQ(run({"export", kCourtyard.string(), "-o", (dir_ / "c.glb").string()}).code, 0);
  EXPECT_EQ(contents(dir_ / "a.glb"), contents(dir_ / "c.glb"));
  for (const char* name : {"a.glb", "b.gltf"}) {
    keep_file_for_validator(dir_ / name);
    GltfFile file = parse_gltf(contents(dir_ / name));
    ASSERT_TRUE(file.errors.empty()) << file.errors.front();
    const std::map<std::string, double> areas = material_areas(file);
    double total = 0.0;
    for (const auto& [material, area] : areas) total += area;
    EXPECT_NEAR(total, 400.0 + 36.0 - 4.0 + 16.0 - 1.0, 1e-9) << name;
  }
}

TEST_F(ExportCli, HelpAndUsage) {
  const Outcome top = run({"--help"});
  EXPECT_EQ(top.code, 0);
  EXPECT_NE(top.out.find("export"), std::string::npos) << top.out;
  const Outcome help = run({"export", "--help"});
  EXPECT_EQ(help.code, 0);
  for (const char* option : {"--obj", "--gltf", "--by-light", "--strict", "--threads", "--quiet"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option << "\n" << help.out;
  }
  EXPECT_EQ(run({"export", kCourtyard.string()}).code, 2);                 // no --obj
  EXPECT_EQ(run({"export", "--obj", (dir_ / "x.obj").string()}).code, 2);  // no input
  EXPECT_EQ(
      run({"export", kCourtyard.string(), "--obj", (dir_ / "x.obj").string(), "--threads", "many"})
          .code,
      2);
  EXPECT_EQ(files(), std::vector<std::string>{});
}

}  // namespace
}  // namespace shadowgen::test
