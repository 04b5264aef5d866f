// End-to-end tests of sun-hours maps, `render --sun-hours` and `export --sun-hours`
// (cli/sun_hours_options.h), on the garden example's database (the sun path of 21 March):
// the picture's paths carry hours the database has on their face, each filled with the
// colour its band has in the legend, and cover what the lit picture covers; the OBJ's
// groups add up to the database's regions by band and to the faces' areas; --bands; and
// the errors: a path the database does not have, a database without sun paths, options
// that do not fit.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "shadowgen/output/database.h"
#include "shadowgen/scene/database_reader.h"
#include "tests/cli/cli_harness.h"
#include "tests/support/gltf_file.h"
#include "tests/support/obj_text.h"

namespace shadowgen::test {
namespace {

const fs::path kScenes = fs::path(SHADOWGEN_EXAMPLES_DIR) / "scenes";

// Area of a planar 3D polygon of the database, {"outer": [[x,y,z],...], "holes": [...]}:
// half the length of Newell's vector of each loop, holes taken away.
double polygon_area(const nlohmann::json& polygon) {
  auto loop_area = [](const nlohmann::json& loop) {
    std::array<double, 3> n{0, 0, 0};
    const std::size_t count = loop.size();
    const auto o = loop[0].get<std::array<double, 3>>();
    for (std::size_t i = 0; i < count; ++i) {
      auto a = loop[i].get<std::array<double, 3>>();
      auto b = loop[(i + 1) % count].get<std::array<double, 3>>();
      for (int k = 0; k < 3; ++k) {
        a[k] -= o[k];
        b[k] -= o[k];
      }
      n[0] += a[1] * b[2] - a[2] * b[1];
      n[1] += a[2] * b[0] - a[0] * b[2];
      n[2] += a[0] * b[1] - a[1] * b[0];
    }
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  };
  double area = loop_area(polygon.at("outer"));
  for (const auto& hole : polygon.value("holes", nlohmann::json::array())) area -= loop_area(hole);
  return area;
}

// One sun-hours region of the database.
struct Region {
  double hours = 0.0;
  double area = 0.0;
};

// The regions of path `path` by face id, and each face's area, from the database's JSON,
// written again with its polygons' coordinates inline (shadowgen-shadowed/1) so that
// their areas are computed here from the numbers themselves.
struct DatabaseRegions {
  std::map<std::string, std::vector<Region>> of_face;
  std::map<std::string, double> face_area;
};

DatabaseRegions database_regions(const fs::path& db, const std::string& path) {
  DatabaseRegions out;
  const nlohmann::json database =
      nlohmann::json::parse(database_json(read_database(db), database::Layout::kInline));
  for (const auto& face : database.at("faces")) {
    const std::string id = face.at("id");
    for (const auto& part : face.at("parts")) out.face_area[id] += polygon_area(part);
    for (const auto& region : face.at("sun_hours").at(path).at("regions")) {
      double area = 0.0;
      for (const auto& polygon : region.at("polygons")) area += polygon_area(polygon);
      out.of_face[id].push_back({region.at("hours").get<double>(), area});
    }
  }
  return out;
}

// A band of the legend as the picture shows it: its swatch's colour and its label.
struct LegendBand {
  std::string colour;
  std::string label;
};

// The legend's caption lines and bands, top to bottom.
struct SvgLegend {
  std::vector<std::string> caption;
  std::vector<LegendBand> bands;
};

SvgLegend legend_of(const std::string& svg) {
  SvgLegend legend;
  const std::size_t start = svg.find("data-legend=\"sun-hours\">");
  if (start == std::string::npos) return legend;
  const std::string text = svg.substr(start, svg.find("</g>", start) - start);
  const std::regex element(
      R"re(<rect [^>]*fill="(#[0-9a-f]{6})"[^>]*/>|<text [^>]*>([^<]*)</text>)re");
  std::string swatch;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), element);
       it != std::sregex_iterator(); ++it) {
    if ((*it)[1].matched) {
      swatch = (*it)[1];
    } else if (swatch.empty()) {
      legend.caption.push_back((*it)[2]);
    } else {
      legend.bands.push_back({swatch, (*it)[2]});
      swatch.clear();
    }
  }
  return legend;
}

// The lower edge of a band from its label: "2–4 h" and "≥ 10 h" begin at 2 and 10.
double band_from(const std::string& label) {
  const std::string at_least = "\u2265 ";
  return std::stod(label.rfind(at_least, 0) == 0 ? label.substr(at_least.size()) : label);
}

// The legend's colour for `hours`: the band with the greatest lower edge not above it.
std::string legend_colour(const SvgLegend& legend, double hours) {
  std::string colour;
  double best = -1.0;
  for (const LegendBand& band : legend.bands) {
    const double from = band_from(band.label);
    if (from <= hours && from > best) {
      best = from;
      colour = band.colour;
    }
  }
  return colour;
}

// "#rrggbb" of an MTL colour, as the SVG writes colours.
std::string hex(const Vec3& colour) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x",
                static_cast<unsigned>(std::lround(255 * colour[0])),
                static_cast<unsigned>(std::lround(255 * colour[1])),
                static_cast<unsigned>(std::lround(255 * colour[2])));
  return text;
}

class SunHoursCli : public CliFolderTest<> {
 protected:
  SunHoursCli() : CliFolderTest("shadowgen-sun-hours") {}

  void SetUp() override {
    CliFolderTest::SetUp();
    garden_ = dir_ / "garden.shadowed.json";
    const Outcome generated =
        run({"generate", (kScenes / "garden.json").string(), "-o", garden_.string()});
    ASSERT_EQ(generated.code, 0) << generated.err;
  }

  // Paths of the picture by face: area (square pixels), and every path's face, hours and
  // fill.
  struct MapPath {
    std::string face;
    double hours = 0.0;
    std::string fill;
    double area = 0.0;
  };
  static std::vector<MapPath> map_paths(const std::string& svg) {
    std::vector<MapPath> paths;
    const std::regex path(
        R"re(<path d="([^"]*)" fill="(#[0-9a-f]{6})" fill-rule="evenodd" data-face="([^"]*)" data-hours="([^"]*)")re");
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator();
         ++it) {
      paths.push_back({(*it)[3], std::stod((*it)[4]), (*it)[2], svg_path_area((*it)[1])});
    }
    return paths;
  }

  fs::path garden_;
};

TEST_F(SunHoursCli, RenderFillsEachVisibleRegionPieceWithItsBandsColourAndHasALegend) {
  const fs::path svg = dir_ / "map.svg";
  const Outcome rendered = run({"render", "--pieces", garden_.string(), "--view", "main",
                                "--sun-hours", "march21", "--svg", svg.string()});
  ASSERT_EQ(rendered.code, 0) << rendered.err;
  EXPECT_EQ(rendered.err, "");  // the path's instants were summed: no warning for a map
  ExpectWellFormedXml(svg, dir_ / "run" / "xmllint");
  const std::string picture = contents(svg);
  EXPECT_EQ(
      shell("rsvg-convert " + quoted(svg.string()) + " -o " + quoted((dir_ / "map.png").string())),
      0);
  // The 800-pixel picture and a 220-pixel legend beside it.
  EXPECT_NE(picture.find("width=\"1020\" height=\"600\""), std::string::npos);

  // The legend: the path and its step, and six bands of two hours, the most on top.
  const SvgLegend legend = legend_of(picture);
  EXPECT_EQ(legend.caption,
            (std::vector<std::string>{"Sun hours: march21", "5 instants, every 120 min"}));
  std::vector<std::string> labels;
  std::set<std::string> colours;
  for (const LegendBand& band : legend.bands) {
    labels.push_back(band.label);
    colours.insert(band.colour);
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"\u2265 10 h", "8\u201310 h", "6\u20138 h",
                                              "4\u20136 h", "2\u20134 h", "0\u20132 h"}));
  EXPECT_EQ(colours.size(), 6u);  // all different
  ASSERT_EQ(legend.bands.size(), 6u);
  EXPECT_EQ(legend.bands.front().colour, "#fde725");  // viridis's ends
  EXPECT_EQ(legend.bands.back().colour, "#440154");

  // Every path: hours of a region of its face in the database, filled with its band's
  // legend colour; no light sets.
  EXPECT_EQ(picture.find("data-lights"), std::string::npos);
  const DatabaseRegions db = database_regions(garden_, "march21");
  const std::vector<MapPath> paths = map_paths(picture);
  ASSERT_GT(paths.size(), 12u);
  std::set<double> hours_seen;
  std::map<std::string, double> map_area;
  for (const MapPath& path : paths) {
    ASSERT_EQ(db.of_face.count(path.face), 1u) << path.face;
    bool found = false;
    for (const Region& region : db.of_face.at(path.face))
      found = found || region.hours == path.hours;
    EXPECT_TRUE(found || path.hours == 0.0) << path.face << " has no region of " << path.hours;
    EXPECT_EQ(path.fill, legend_colour(legend, path.hours)) << path.face << ", " << path.hours;
    hours_seen.insert(path.hours);
    map_area[path.face] += path.area;
  }
  EXPECT_EQ(hours_seen, (std::set<double>{0, 2, 4, 6, 8, 10}));

  // The map covers, face by face, what the lit picture of the same view covers.
  const fs::path lit_svg = dir_ / "lit.svg";
  ASSERT_EQ(
      run({"render", "--pieces", garden_.string(), "--view", "main", "--svg", lit_svg.string()})
          .code,
      0);
  const std::string lit = contents(lit_svg);
  const std::regex lit_path(
      R"re(<path d="([^"]*)" fill="#[0-9a-f]{6}" fill-rule="evenodd" data-face="([^"]*)")re");
  std::map<std::string, double> lit_area;
  for (auto it = std::sregex_iterator(lit.begin(), lit.end(), lit_path);
       it != std::sregex_iterator(); ++it) {
    lit_area[(*it)[2]] += svg_path_area((*it)[1]);
  }
  EXPECT_EQ(map_area.size(), lit_area.size());
  for (const auto& [face, area] : lit_area) {
    EXPECT_LE(relative_error(map_area[face], area), 1e-9) << face;
  }
}

TEST_F(SunHoursCli, ExportGroupsAddUpToTheDatabasesRegionsByBandAndToEachFace) {
  const fs::path obj_path = dir_ / "map.obj";
  const Outcome exported =
      run({"export", garden_.string(), "--obj", obj_path.string(), "--sun-hours", "march21"});
  ASSERT_EQ(exported.code, 0) << exported.err;
  EXPECT_EQ(exported.err, "");
  const ObjText obj = parse_obj(contents(obj_path));
  ASSERT_TRUE(obj.errors.empty()) << obj.errors.front();
  const MtlText mtl = parse_mtl(contents(dir_ / "map.mtl"));
  ASSERT_TRUE(mtl.errors.empty()) << mtl.errors.front();
  EXPECT_EQ(mtl.order, (std::vector<std::string>{"0-2h", "2-4h", "4-6h", "6-8h", "8-10h", "10h+"}));

  // The database's region areas by "<face>@<band>", bands of two hours.
  const DatabaseRegions db = database_regions(garden_, "march21");
  std::map<std::string, double> expected;
  for (const auto& [face, regions] : db.of_face) {
    for (const Region& region : regions) {
      const int from = 2 * static_cast<int>(region.hours / 2);
      const std::string band =
          from >= 10 ? "10h+" : std::to_string(from) + "-" + std::to_string(from + 2) + "h";
      expected[face + "@" + band] += region.area;
    }
  }
  std::map<std::string, double> face_sums;
  double worst = 0.0;
  for (const ObjGroup& group : obj.groups) {
    ASSERT_EQ(expected.count(group.name), 1u) << group.name;
    const std::size_t at = group.name.rfind('@');
    const std::string face = group.name.substr(0, at), band = group.name.substr(at + 1);
    double area = 0.0;
    for (const ObjTriangle& t : group.triangles) {
      EXPECT_EQ(t.material, band) << group.name;
      area += test::area(t);
    }
    const double error = relative_error(area, expected.at(group.name));
    EXPECT_LE(error, 1e-9) << group.name << ": " << area << " vs " << expected.at(group.name);
    worst = std::max(worst, error);
    face_sums[face] += area;
  }
  EXPECT_EQ(obj.groups.size(), expected.size());
  ASSERT_EQ(face_sums.size(), db.face_area.size());
  for (const auto& [face, area] : db.face_area) {
    EXPECT_LE(relative_error(face_sums[face], area), 1e-9) << face;
  }
  std::printf("garden: %zu groups, areas within %.3g of the database's regions\n",
              obj.groups.size(), worst);

  // The materials' colours are the legend's.
  const fs::path svg = dir_ / "map.svg";
  ASSERT_EQ(run({"render", garden_.string(), "--view", "main", "--sun-hours", "march21", "--svg",
                 svg.string()})
                .code,
            0);
  const SvgLegend legend = legend_of(contents(svg));
  ASSERT_EQ(legend.bands.size(), mtl.order.size());
  for (std::size_t b = 0; b < mtl.order.size(); ++b) {
    EXPECT_EQ(hex(mtl.kd.at(mtl.order[b])), legend.bands[legend.bands.size() - 1 - b].colour)
        << mtl.order[b];
  }
}

// export --gltf --sun-hours: one material per band, coloured and named as the OBJ's; each
// band's triangles add up to the database's regions in it, and the pieces' hours are the
// regions' (float32 positions around the garden's centre: within 1e-6).
TEST_F(SunHoursCli, GltfBandsAddUpToTheDatabasesRegions) {
  const fs::path glb = dir_ / "map.glb";
  const Outcome exported =
      run({"export", garden_.string(), "--gltf", glb.string(), "--sun-hours", "march21"});
  ASSERT_EQ(exported.code, 0) << exported.err;
  EXPECT_EQ(exported.err, "");
  keep_file_for_validator(glb);
  GltfFile file = parse_gltf(contents(glb));
  ASSERT_TRUE(file.errors.empty()) << file.errors.front();
  std::vector<std::string> names;
  for (const auto& material : file.json["materials"]) names.push_back(material["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"0-2h", "2-4h", "4-6h", "6-8h", "8-10h", "10h+"}));

  std::map<std::string, double> expected;
  std::set<double> hours;
  for (const auto& [face, regions] : database_regions(garden_, "march21").of_face) {
    for (const Region& region : regions) {
      const int from = 2 * static_cast<int>(region.hours / 2);
      expected[from >= 10 ? "10h+" : std::to_string(from) + "-" + std::to_string(from + 2) + "h"] +=
          region.area;
      hours.insert(region.hours);
    }
  }
  const std::map<std::string, double> areas = material_areas(file);
  EXPECT_EQ(areas.size(), expected.size());
  for (const auto& [band, area] : expected) {
    EXPECT_LE(relative_error(areas.at(band), area), 1e-6) << band;
  }
  for (const auto& mesh : file.json["meshes"]) {
    for (const auto& h : mesh["extras"]["pieces"]["hours"]) {
      EXPECT_EQ(hours.count(h.get<double>()), 1u) << h;
    }
  }
  EXPECT_EQ(file.json["scenes"][0]["extras"]["sun_path"]["id"], "march21");

  // The scene's site, from the scene.
  const fs::path from_scene = dir_ / "scene.gltf";
  ASSERT_EQ(run({"export", (kScenes / "garden.json").string(), "--gltf", from_scene.string(),
                 "--sun-hours", "march21"})
                .code,
            0);
  keep_file_for_validator(from_scene);
  GltfFile scene = parse_gltf(contents(from_scene));
  ASSERT_TRUE(scene.errors.empty()) << scene.errors.front();
  EXPECT_EQ(scene.json["scenes"][0]["extras"]["site"], nlohmann::json({{"latitude_deg", 51.4779},
                                                                       {"longitude_deg", -0.0015},
                                                                       {"elevation_m", 45.0},
                                                                       {"utc_offset_h", 0.0},
                                                                       {"north_axis_deg", 0.0}}));
  EXPECT_EQ(material_areas(scene), areas);
}

TEST_F(SunHoursCli, BandsChooseTheEdges) {
  const fs::path svg = dir_ / "map.svg";
  ASSERT_EQ(run({"render", garden_.string(), "--view", "main", "--sun-hours", "march21", "--bands",
                 "2,6", "--svg", svg.string()})
                .code,
            0);
  std::vector<std::string> labels;
  for (const LegendBand& band : legend_of(contents(svg)).bands) labels.push_back(band.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"\u2265 6 h", "2\u20136 h", "0\u20132 h"}));
  const fs::path obj = dir_ / "map.obj";
  ASSERT_EQ(run({"export", garden_.string(), "--obj", obj.string(), "--sun-hours", "march21",
                 "--bands", "2", "--bands", "6"})
                .code,
            0);
  EXPECT_EQ(parse_mtl(contents(dir_ / "map.mtl")).order,
            (std::vector<std::string>{"0-2h", "2-6h", "6h+"}));
}

TEST_F(SunHoursCli, AnUnknownPathOrNoSunPathIsBadInputNamingTheFile) {
  const std::string svg = (dir_ / "map.svg").string(), obj = (dir_ / "map.obj").string();
  const std::string expected =
      "shadowgen: " + garden_.string() + ": has no sun path 'june21' (its sun paths: 'march21')\n";
  const Outcome render =
      run({"render", garden_.string(), "--view", "main", "--sun-hours", "june21", "--svg", svg});
  EXPECT_EQ(render.code, 1);
  EXPECT_EQ(render.err, expected);
  const Outcome exported = run({"export", garden_.string(), "--obj", obj, "--sun-hours", "june21"});
  EXPECT_EQ(exported.code, 1);
  EXPECT_EQ(exported.err, expected);

  const fs::path courtyard = dir_ / "courtyard.shadowed.json";
  ASSERT_EQ(run({"generate", (kScenes / "courtyard.json").string(), "-o", courtyard.string()}).code,
            0);
  const std::string none = "shadowgen: " + courtyard.string() +
                           ": has no sun path (a `sun` light with from, to and step_min), so no "
                           "sun hours of 'march21'\n";
  const Outcome render_none =
      run({"render", courtyard.string(), "--view", "main", "--sun-hours", "march21", "--svg", svg});
  EXPECT_EQ(render_none.code, 1);
  EXPECT_EQ(render_none.err, none);
  const Outcome export_none =
      run({"export", courtyard.string(), "--obj", obj, "--sun-hours", "march21"});
  EXPECT_EQ(export_none.code, 1);
  EXPECT_EQ(export_none.err, none);
  // A scene is checked as soon as it is read, with the same message naming it.
  for (const char* name : {"garden.json", "courtyard.json"}) {
    const std::string scene = (kScenes / name).string();
    const Outcome from_scene = run({"export", scene, "--obj", obj, "--sun-hours", "june21"});
    EXPECT_EQ(from_scene.code, 1);
    EXPECT_EQ(from_scene.err,
              "shadowgen: " + scene + ": " +
                  (std::string(name) == "garden.json"
                       ? "has no sun path 'june21' (its sun paths: 'march21')\n"
                       : "has no sun path (a `sun` light with from, to and step_min), so no "
                         "sun hours of 'june21'\n"));
  }
  EXPECT_EQ(files(), (std::vector<std::string>{"courtyard.shadowed.json", "garden.shadowed.json"}));
}

TEST_F(SunHoursCli, OptionsThatDoNotFitAreUsageErrors) {
  const std::string db = garden_.string(), svg = (dir_ / "map.svg").string();
  const std::string obj = (dir_ / "map.obj").string();
  auto render = [&](std::vector<std::string> more) {
    std::vector<std::string> args{"render", db, "--view", "main", "--svg", svg};
    args.insert(args.end(), more.begin(), more.end());
    return run(args);
  };
  // --sun-hours draws one path whole: --lights has nothing to choose.
  const Outcome lights = render({"--sun-hours", "march21", "--lights", "march21"});
  EXPECT_EQ(lights.code, 2);
  EXPECT_NE(lights.err.find("--lights excludes --sun-hours"), std::string::npos) << lights.err;
  const Outcome export_lights =
      run({"export", db, "--obj", obj, "--sun-hours", "march21", "--lights", "march21"});
  EXPECT_EQ(export_lights.code, 2);
  EXPECT_NE(export_lights.err.find("--lights excludes --sun-hours"), std::string::npos)
      << export_lights.err;
  EXPECT_EQ(render({"--bands", "2"}).code, 2);  // bands of no map
  EXPECT_EQ(run({"export", db, "--obj", obj, "--bands", "2"}).code, 2);
  EXPECT_EQ(render({"--sun-hours", "march21", "--bands", "0"}).code, 2);
  EXPECT_EQ(render({"--sun-hours", "march21", "--bands", "x"}).code, 2);
  const Outcome order = render({"--sun-hours", "march21", "--bands", "4,2"});
  EXPECT_EQ(order.code, 2);
  EXPECT_EQ(order.err.rfind("shadowgen: --bands: band edges must be in increasing order (4 "
                            "before 2)\n",
                            0),
            0u)
      << order.err;
  const Outcome above =
      run({"export", db, "--obj", obj, "--sun-hours", "march21", "--bands", "11"});
  EXPECT_EQ(above.code, 2);
  EXPECT_NE(above.err.find("the band edge 11 is above the 10 h that sun path 'march21' gives at "
                           "most"),
            std::string::npos)
      << above.err;
  EXPECT_EQ(files(), std::vector<std::string>{"garden.shadowed.json"});

  for (const char* command : {"render", "export"}) {
    const Outcome help = run({command, "--help"});
    EXPECT_EQ(help.code, 0);
    EXPECT_NE(help.out.find("--sun-hours"), std::string::npos) << command;
    EXPECT_NE(help.out.find("--bands"), std::string::npos) << command;
  }
}

}  // namespace
}  // namespace shadowgen::test
