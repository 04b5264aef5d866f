// The viewer's model (shadowgen/viewer/viewer_model.h) read back as a glTF reader reads
// it: the GLB container, the triangles of each group against the hand-computed areas of
// its light set or band, the faces they name, the axes and origin, and the page's
// description; and the page's folder (viewer_page.h).

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
#include "shadowgen/viewer/detail/glb_file.h"
#include "shadowgen/viewer/viewer_page.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/support/relative_error.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

using test::relative_error;

// A GLB read back: its JSON and its binary chunk.
struct Glb {
  nlohmann::json json;
  std::string bin;
};

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

Glb read_glb(const std::string& bytes) {
  Glb glb;
  EXPECT_GE(bytes.size(), 28u);
  EXPECT_EQ(u32(bytes, 0), 0x46546C67u);  // "glTF"
  EXPECT_EQ(u32(bytes, 4), 2u);
  EXPECT_EQ(u32(bytes, 8), bytes.size());
  const std::uint32_t json_length = u32(bytes, 12);
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(u32(bytes, 16), 0x4E4F534Au);  // "JSON"
  glb.json = nlohmann::json::parse(bytes.substr(20, json_length));
  const std::size_t bin_at = 20 + json_length;
  const std::uint32_t bin_length = u32(bytes, bin_at);
  EXPECT_EQ(bin_length % 4, 0u);
  EXPECT_EQ(u32(bytes, bin_at + 4), 0x004E4942u);  // "BIN\0"
  EXPECT_EQ(bin_at + 8 + bin_length, bytes.size());
  glb.bin = bytes.substr(bin_at + 8, bin_length);
  return glb;
}

// The floats of accessor `a`.
std::vector<float> floats(const Glb& glb, std::size_t a) {
  const nlohmann::json& accessor = glb.json["accessors"][a];
  const nlohmann::json& view = glb.json["bufferViews"][accessor["bufferView"].get<std::size_t>()];
  EXPECT_EQ(accessor["componentType"], 5126);
  std::vector<float> out(view["byteLength"].get<std::size_t>() / sizeof(float));
  std::memcpy(out.data(), glb.bin.data() + view["byteOffset"].get<std::size_t>(),
              out.size() * sizeof(float));
  return out;
}

// The unsigned integers of accessor `a`.
std::vector<std::uint32_t> uints(const Glb& glb, std::size_t a) {
  const nlohmann::json& accessor = glb.json["accessors"][a];
  const nlohmann::json& view = glb.json["bufferViews"][accessor["bufferView"].get<std::size_t>()];
  EXPECT_EQ(accessor["componentType"], 5125);
  std::vector<std::uint32_t> out(view["byteLength"].get<std::size_t>() / sizeof(std::uint32_t));
  std::memcpy(out.data(), glb.bin.data() + view["byteOffset"].get<std::size_t>(),
              out.size() * sizeof(std::uint32_t));
  return out;
}

// Per group of the page: the area of its triangles, and the faces they belong to.
struct GroupTriangles {
  double area = 0.0;
  std::set<std::size_t> faces;
};

std::map<std::size_t, GroupTriangles> group_triangles(const Glb& glb) {
  std::map<std::size_t, GroupTriangles> groups;
  for (const nlohmann::json& node : glb.json["nodes"]) {
    if (!node.contains("extras") || !node["extras"].contains("group")) continue;
    const nlohmann::json& primitive =
        glb.json["meshes"][node["mesh"].get<std::size_t>()]["primitives"][0];
    EXPECT_EQ(primitive["mode"], 4);
    const std::vector<float> p = floats(glb, primitive["attributes"]["POSITION"]);
    const std::vector<float> f = floats(glb, primitive["attributes"]["_FACE"]);
    const std::vector<std::uint32_t> index = uints(glb, primitive["indices"]);
    EXPECT_EQ(p.size(), 3 * f.size());
    EXPECT_EQ(index.size() % 3, 0u);
    GroupTriangles& group = groups[node["extras"]["group"].get<std::size_t>()];
    const auto vertex = [&](std::uint32_t i) {
      return glm::dvec3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    };
    for (std::size_t t = 0; t + 2 < index.size(); t += 3) {
      const std::uint32_t i = index[t], j = index[t + 1], k = index[t + 2];
      EXPECT_LT(std::max({i, j, k}), f.size());
      if (std::max({i, j, k}) >= f.size()) return groups;
      const glm::dvec3 n = glm::cross(vertex(j) - vertex(i), vertex(k) - vertex(i));
      group.area += 0.5 * std::sqrt(glm::dot(n, n));
      EXPECT_EQ(f[i], f[j]);
      EXPECT_EQ(f[i], f[k]);
      group.faces.insert(static_cast<std::size_t>(f[i]));
    }
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
  const Glb glb = read_glb(model.glb);
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
  const Glb glb = read_glb(model.glb);
  for (const nlohmann::json& node : glb.json["nodes"]) {
    EXPECT_EQ(node["translation"], nlohmann::json({5.0, 0.5, -5.0}));
  }
  // The outlines: each face part's loop as pairs of points, the ground's first edge from
  // (0,0,0) to (10,0,0).
  const nlohmann::json& outline_node = glb.json["nodes"].back();
  EXPECT_EQ(outline_node["extras"]["outline"], true);
  const nlohmann::json& lines =
      glb.json["meshes"][outline_node["mesh"].get<std::size_t>()]["primitives"][0];
  EXPECT_EQ(lines["mode"], 1);
  const std::vector<float> p = floats(glb, lines["attributes"]["POSITION"]);
  ASSERT_EQ(p.size(), 2u * 3u * 8u);  // two faces of four edges
  EXPECT_EQ(std::vector<float>(p.begin(), p.begin() + 6),
            (std::vector<float>{-5.0f, -0.5f, 5.0f, 5.0f, -0.5f, 5.0f}));
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
  shadowed.scene.site.reset();
  EXPECT_NEAR(
      nlohmann::json::parse(viewer_model(shadowed).description)["north_axis_deg"].get<double>(),
      30.0, 1e-9);
  shadowed.scene.lights[0].sun.reset();  // a plain directional light says nothing of north
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
  const std::map<std::size_t, GroupTriangles> groups = group_triangles(read_glb(model.glb));
  EXPECT_EQ(groups.at(0).area, 1.0);
  EXPECT_EQ(groups.at(1).area, 3.0);
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
  EXPECT_EQ(detail::base64(""), "");
  EXPECT_EQ(detail::base64("f"), "Zg==");
  EXPECT_EQ(detail::base64("fo"), "Zm8=");
  EXPECT_EQ(detail::base64("foo"), "Zm9v");
  EXPECT_EQ(detail::base64("foob"), "Zm9vYg==");
  EXPECT_EQ(detail::base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(detail::base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(detail::base64(std::string("\xff\xfe\x00", 3)), "//4A");
}

TEST(GlbFile, AMeshWithoutWholeVerticesIsACallersMistake) {
  detail::GlbMesh mesh;
  mesh.name = "empty";
  EXPECT_THROW(detail::glb_file({&mesh, 1}, glm::dvec3(0.0)), std::invalid_argument);
  mesh.positions = {0.0f, 0.0f};
  EXPECT_THROW(detail::glb_file({&mesh, 1}, glm::dvec3(0.0)), std::invalid_argument);
}

TEST(GlbFile, NoMeshIsOneEmptySceneWithoutABinaryChunk) {
  const std::string glb = detail::glb_file({}, glm::dvec3(0.0));
  ASSERT_EQ(u32(glb, 8), glb.size());
  EXPECT_EQ(glb.size(), 20 + u32(glb, 12));
  const nlohmann::json json = nlohmann::json::parse(glb.substr(20));
  EXPECT_EQ(json["scenes"], nlohmann::json::parse(R"([{"nodes": []}])"));
  EXPECT_FALSE(json.contains("buffers"));
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
