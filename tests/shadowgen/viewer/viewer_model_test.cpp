// The viewer's model (shadowgen/viewer/viewer_model.h) read back as a glTF reader reads
// it (tests/support/gltf_file.h; each file kept for the Khronos validator): the triangles
// of each group against the hand-computed areas of its light set or band, the faces they
// name, the outlines, the axes and origin, and the page's description; and the page's
// folder (viewer_page.h).

#include "shadowgen/viewer/viewer_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/viewer/detail/base64.h"
#include "shadowgen/viewer/viewer_page.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/support/gltf_file.h"
#include "tests/support/relative_error.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

using test::relative_error;

// The model read back by the tests' own glTF reader, kept for the Khronos validator (CTest's
// gltf.validator), with no reading error.
test::GltfFile read_model(const ViewerModel& model) {
  test::keep_for_validator(model.glb, ".glb");
  test::GltfFile file = test::parse_gltf(model.glb);
  EXPECT_TRUE(file.errors.empty()) << file.errors.front();
  EXPECT_EQ(model.glb.compare(0, 4, "glTF"), 0);  // binary
  return file;
}

// Per group of the page (the file's material), the area of its triangles and the faces
// their vertices name (_FACE).
struct GroupTriangles {
  double area = 0.0;
  std::set<std::size_t> faces;
};

std::map<std::size_t, GroupTriangles> group_triangles(test::GltfFile& file) {
  std::map<std::size_t, GroupTriangles> groups;
  for (std::size_t m = 0; m < file.json["meshes"].size(); ++m) {
    const nlohmann::json& primitive = file.json["meshes"][m]["primitives"][0];
    if (primitive.value("mode", 4) != 4) continue;
    GroupTriangles& group = groups[primitive["material"].get<std::size_t>()];
    for (const test::GltfTriangle& t : test::mesh_triangles(file, m)) {
      group.area += test::triangle_area(t);
    }
    const std::vector<double> faces = test::mesh_scalars(file, m, "_FACE");
    EXPECT_EQ(faces.size(),
              file.json["accessors"][primitive["attributes"]["POSITION"].get<int>()]["count"]
                  .get<std::size_t>());
    for (const double f : faces) group.faces.insert(static_cast<std::size_t>(f));
  }
  return groups;
}

// Float32 positions of coordinates up to 10 keep areas to about 1e-7 of the whole.
constexpr double kFloatAreaTolerance = 1e-6;

TEST(ViewerModel, EachLightSetsTrianglesAddUpToItsHandComputedArea) {
  // kTwoLights: on the ground, [3,6] × [3,7] in both shadows (12), [6,7] × [3,7] under the
  // slant light's shadow alone (lit by "down": 4), [2,3] × [3,7] under down's alone (4),
  // the rest (80) and the square (16) lit by both.
  const ViewerModel model = viewer_model(test::generated(test::kTwoLights));
  const nlohmann::json meta = nlohmann::json::parse(model.description);
  ASSERT_EQ(meta["groups"].size(), 4u);
  const std::vector<std::string> names = {"shadow", "down", "slant", "down+slant"};
  const std::vector<double> areas = {12.0, 4.0, 4.0, 96.0};
  test::GltfFile glb = read_model(model);
  const std::map<std::size_t, GroupTriangles> groups = group_triangles(glb);
  ASSERT_EQ(groups.size(), 4u);
  for (std::size_t g = 0; g < 4; ++g) {
    SCOPED_TRACE(names[g]);
    EXPECT_EQ(meta["groups"][g]["name"], names[g]);
    EXPECT_LT(relative_error(groups.at(g).area, areas[g]), kFloatAreaTolerance);
  }
  EXPECT_EQ(groups.at(0).faces, (std::set<std::size_t>{0}));
  EXPECT_EQ(groups.at(3).faces, (std::set<std::size_t>{0, 1}));
  // The colour rule of obj_export.h: shadow 0.2, one of two equal lights 0.6, both white.
  EXPECT_EQ(meta["groups"][0]["colour"], nlohmann::json({0.2, 0.2, 0.2}));
  EXPECT_EQ(meta["groups"][3]["colour"], nlohmann::json({1.0, 1.0, 1.0}));
  EXPECT_EQ(meta["groups"][1]["lights"], nlohmann::json::array({0}));
  EXPECT_EQ(meta["groups"][3]["lights"], nlohmann::json({0, 1}));
  // Materials: unlit, double-sided, named as the group, the colour in linear sRGB.
  const nlohmann::json& material = glb.json["materials"][0];
  EXPECT_EQ(material["name"], "shadow");
  EXPECT_EQ(material["doubleSided"], true);
  EXPECT_TRUE(material["extensions"].contains("KHR_materials_unlit"));
  EXPECT_NEAR(material["pbrMetallicRoughness"]["baseColorFactor"][0].get<double>(),
              std::pow((0.2 + 0.055) / 1.055, 2.4), 1e-15);
}

TEST(ViewerModel, TheDescriptionGivesEachFacesIdAreaAndLitAreaPerLight) {
  const ViewerModel model = viewer_model(test::generated(test::kTwoLights));
  const nlohmann::json meta = nlohmann::json::parse(model.description);
  ASSERT_EQ(meta["faces"].size(), 2u);
  EXPECT_EQ(meta["faces"][0]["id"], "ground");
  EXPECT_EQ(meta["faces"][0]["area"], 100.0);
  EXPECT_NEAR(meta["faces"][0]["lit"][0].get<double>(), 84.0, 1e-12);
  EXPECT_NEAR(meta["faces"][0]["lit"][1].get<double>(), 84.0, 1e-12);
  EXPECT_EQ(meta["faces"][1]["id"], "square");
  EXPECT_EQ(meta["faces"][1]["lit"], nlohmann::json({16.0, 16.0}));
  EXPECT_EQ(meta["lights"][0]["id"], "down");
  EXPECT_EQ(meta["lights"][1]["id"], "slant");
  EXPECT_EQ(meta["total_intensity"], nlohmann::json({2.0, 2.0, 2.0}));
  EXPECT_FALSE(meta.contains("north_axis_deg"));  // no site
}

TEST(ViewerModel, PositionsAreRelativeToTheSceneCentreInGltfAxes) {
  // The scene's box is [0,10] × [0,10] × [0,1]: centre (5, 5, 0.5), in glTF's axes
  // (x, z, -y) = (5, 0.5, -5). The ground's corner (10, 10, 0) is (5, -0.5, -5) from it.
  const ViewerModel model = viewer_model(test::generated(test::kTwoLights));
  const nlohmann::json meta = nlohmann::json::parse(model.description);
  EXPECT_EQ(meta["origin"], nlohmann::json({5.0, 5.0, 0.5}));
  test::GltfFile glb = read_model(model);
  for (std::size_t m = 0; m < glb.json["meshes"].size(); ++m) {
    EXPECT_EQ(test::mesh_translation(glb, m), glm::dvec3(5.0, 0.5, -5.0));
  }
  // The outlines, the last mesh: each face part's loop as pairs of points, the ground's
  // first edge from (0,0,0) to (10,0,0).
  const std::size_t last = glb.json["meshes"].size() - 1;
  EXPECT_EQ(glb.json["nodes"].back()["name"], "outlines");
  const std::vector<std::array<glm::dvec3, 2>> lines = test::mesh_lines(glb, last);
  ASSERT_EQ(lines.size(), 8u);  // two faces of four edges
  EXPECT_EQ(lines[0][0], glm::dvec3(-5.0, -0.5, 5.0));
  EXPECT_EQ(lines[0][1], glm::dvec3(5.0, -0.5, 5.0));
  EXPECT_TRUE(glb.errors.empty()) << glb.errors.front();
}

TEST(ViewerModel, TheNorthAxisIsTheSitesOrElseWhatASunInstantSays) {
  // A site whose +y is 30° clockwise from north, and a sun at 10:00, at some azimuth A: its
  // light comes from A clockwise of north, A − 30 clockwise of +y. A database keeps the sun
  // but not the site: the north axis comes back from the two.
  ShadowedScene shadowed = test::generated(R"({"format": "shadowgen-scene/1",
    "polygons": [{"id": "g", "outer": [[0,0,0],[4,0,0],[4,4,0],[0,4,0]]}],
    "site": {"latitude_deg": 51.5, "longitude_deg": 0, "utc_offset_h": 0, "north_axis_deg": 30},
    "lights": [{"id": "sun", "type": "sun", "time": "2026-03-21T10:00"}]})");
  EXPECT_EQ(nlohmann::json::parse(viewer_model(shadowed).description)["north_axis_deg"], 30.0);
  shadowed.edit_scene([&](Scene& scene) { scene.site.reset(); });
  EXPECT_NEAR(
      nlohmann::json::parse(viewer_model(shadowed).description)["north_axis_deg"].get<double>(),
      30.0, 1e-9);
  // a plain directional light says nothing of north
  shadowed.edit_scene([](Scene& scene) { scene.lights[0].sun.reset(); });
  EXPECT_FALSE(
      nlohmann::json::parse(viewer_model(shadowed).description).contains("north_axis_deg"));
}

TEST(ViewerModel, SunHoursBandsHoldTheirRegionsAndFacesTheirMeanHours) {
  // sun_path_by_hand: [0,1] lit at no instant (0 h), [1,3] at three (1.5 h), [3,4] at four
  // (2 h). Bands from 1 h: 0–1 h holds 1, ≥ 1 h holds 3; the mean is 5 / 4 h.
  const ShadowedScene shadowed = test::sun_path_by_hand();
  const std::vector<double> edges = {1.0};
  const HourBands bands = hour_bands(shadowed.sun_paths[0], edges);
  const ViewerModel model = viewer_model(shadowed, shadowed.sun_paths[0], bands);
  const nlohmann::json meta = nlohmann::json::parse(model.description);
  ASSERT_EQ(meta["groups"].size(), 2u);
  EXPECT_EQ(meta["groups"][0]["name"], "0-1h");
  EXPECT_EQ(meta["groups"][1]["name"], "1h+");
  EXPECT_EQ(meta["groups"][1]["from"], 1.0);
  EXPECT_EQ(meta["caption"][0], "Sun hours: p");
  EXPECT_EQ(meta["faces"][0]["hours"], 1.25);
  EXPECT_FALSE(meta["faces"][0].contains("lit"));
  test::GltfFile glb = read_model(model);
  const std::map<std::size_t, GroupTriangles> groups = group_triangles(glb);
  EXPECT_EQ(groups.at(0).area, 1.0);
  EXPECT_EQ(groups.at(1).area, 3.0);
  EXPECT_EQ(glb.json["materials"][1]["name"], "1h+");
}

TEST(ViewerModel, ASunPathWithoutRegionsIsRefusedNamingTheFile) {
  ShadowedScene shadowed = test::sun_path_by_hand();
  shadowed.sun_paths[0].regions_kept = false;
  shadowed.sun_paths[0].regions.clear();
  const HourBands bands = hour_bands(shadowed.sun_paths[0]);
  try {
    viewer_model(shadowed, shadowed.sun_paths[0], bands);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("test.json: ", 0), 0u) << e.what();
  }
}

TEST(ViewerModel, TheScriptHandsThePageTheDescriptionAndTheGlbInBase64) {
  ViewerModel model;
  model.description = R"({"groups":[]})";
  model.glb = "foobar";
  EXPECT_EQ(viewer_model_script(model),
            "window.shadowgenModel = {\"meta\": {\"groups\":[]}, \"glb\": \"Zm9vYmFy\"};\n");
}

TEST(Base64, EncodesTheTestVectorsOfRfc4648) {
  EXPECT_EQ(viewer::detail::base64(""), "");
  EXPECT_EQ(viewer::detail::base64("f"), "Zg==");
  EXPECT_EQ(viewer::detail::base64("fo"), "Zm8=");
  EXPECT_EQ(viewer::detail::base64("foo"), "Zm9v");
  EXPECT_EQ(viewer::detail::base64("foob"), "Zm9vYg==");
  EXPECT_EQ(viewer::detail::base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(viewer::detail::base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(viewer::detail::base64(std::string("\xff\xfe\x00", 3)), "//4A");
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ViewerPage, WritesTheAssetsAndTheModelScriptIntoTheFolder) {
  const test::TempFolder folder("viewer-page");
  const std::filesystem::path assets = folder.path() / "assets";
  std::filesystem::create_directory(assets);
  std::ofstream(assets / "index.html") << "<html></html>";
  std::ofstream(assets / "viewer.js") << "/* viewer */";
  write_viewer_page(folder.path() / "page", assets, "window.shadowgenModel = {};\n");
  EXPECT_EQ(read_text(folder.path() / "page" / "index.html"), "<html></html>");
  EXPECT_EQ(read_text(folder.path() / "page" / "viewer.js"), "/* viewer */");
  EXPECT_EQ(read_text(folder.path() / "page" / "model.js"), "window.shadowgenModel = {};\n");
}

TEST(ViewerPage, AFileWhereTheFolderShouldBeIsAnErrorNamingIt) {
  const test::TempFolder folder("viewer-page");
  const std::filesystem::path taken = folder.write("taken", "a file");
  try {
    write_viewer_page(taken, folder.path(), "");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write the viewer page into '" + taken.string() + "': not a folder");
  }
  EXPECT_EQ(read_text(taken), "a file");
}

TEST(ViewerPage, AnAssetsFolderWithoutThePageIsAnErrorSayingSo) {
  const test::TempFolder folder("viewer-assets");
  ::setenv("SHADOWGEN_VIEWER_ASSETS", folder.path().c_str(), 1);
  try {
    viewer_assets_folder();
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "SHADOWGEN_VIEWER_ASSETS: '" + folder.path().string() +
                                         "' does not hold the viewer page's index.html and "
                                         "viewer.js");
  }
  ::unsetenv("SHADOWGEN_VIEWER_ASSETS");
}

}  // namespace
}  // namespace shadowgen
