// glTF models named by a scene, through `shadowgen generate` and `report`: a good one gives
// its faces' ids in the report; each kind of bad one exits 1 with one line naming the glTF
// file, the node, mesh and primitive where one is at fault, and what is wrong, prints
// nothing on stdout and leaves no output behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_harness.h"
#include "tests/shadowgen/gltf/gltf_builder.h"

namespace shadowgen::test {
namespace {

// A scene naming the model file `model`, under an oblique sun.
std::string scene_naming(const std::string& model) {
  return R"({"format": "shadowgen-scene/1",
  "meshes": [{"id": "house", "file": ")" +
         model + R"("}],
  "lights": [{"id": "sun", "type": "directional", "direction": [-0.3, 0.2, -1]}]})";
}

// The scene's nodes: node 0, "roof", places mesh 0, whose one primitive has `primitive`
// (its attributes and more, without braces).
std::string one_primitive(const std::string& primitive) {
  return R"("scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"name": "roof", "mesh": 0}],
  "meshes": [{"name": "tiles", "primitives": [{)" +
         primitive + "}]}]";
}

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

struct BadModel {
  const char* name;
  std::string file_name;                                   // the model's name in the scene
  std::vector<std::pair<std::string, std::string>> files;  // what the test writes (path, bytes)
  std::string message;  // stderr without "shadowgen: ", the test's folder as "<dir>"
};

void PrintTo(const BadModel& c, std::ostream* os) { *os << c.name; }

std::vector<BadModel> bad_models() {
  std::vector<BadModel> cases;
  {
    GltfBuilder b;
    const int p = b.positions(kTriangle);
    const std::string whole =
        b.glb(one_primitive(R"("attributes": {"POSITION": )" + std::to_string(p) + "}"));
    cases.push_back({"truncated_glb",
                     "house.glb",
                     {{"house.glb", whole.substr(0, 100)}},
                     "<dir>/house.glb: not a well-formed binary glTF file: is truncated: its "
                     "header gives a length of " +
                         std::to_string(whole.size()) + " bytes, the file has 100"});
  }
  {
    GltfBuilder b;
    const int p = b.positions(kTriangle);
    cases.push_back(
        {"missing_buffer_file",
         "house.gltf",
         {{"house.gltf", b.gltf_external(one_primitive(R"("attributes": {"POSITION": )" +
                                                       std::to_string(p) + "}"),
                                         "house.bin")}},
         "<dir>/house.gltf: buffers[0]: file <dir>/house.bin: no such file"});
  }
  {
    GltfBuilder b;
    const int p = b.positions(kTriangle);
    cases.push_back(
        {"draco_required",
         "house.gltf",
         {{"house.gltf",
           b.gltf_embedded(
               R"("extensionsRequired": ["KHR_draco_mesh_compression"], )" +
               one_primitive(R"("attributes": {"POSITION": )" + std::to_string(p) + "}"))}},
         "<dir>/house.gltf: extensionsRequired[0]: the file requires "
         "'KHR_draco_mesh_compression' (Draco-compressed meshes), which shadowgen does not "
         "read"});
  }
  {
    GltfBuilder b;
    const int p = b.positions(kTriangle);
    cases.push_back(
        {"line_strip",
         "house.gltf",
         {{"house.gltf", b.gltf_embedded(one_primitive(R"("attributes": {"POSITION": )" +
                                                       std::to_string(p) + R"(}, "mode": 3)"))}},
         "<dir>/house.gltf: node 'roof' (0), mesh 'tiles' (0), primitive 0: mode 3 "
         "(LINE_STRIP) draws no faces: shadowgen reads TRIANGLES, TRIANGLE_STRIP "
         "and TRIANGLE_FAN"});
  }
  {
    GltfBuilder b;
    const int p = b.positions(kTriangle);
    const int i = b.indices({0, 1, 3});
    cases.push_back({"index_out_of_range",
                     "house.gltf",
                     {{"house.gltf", b.gltf_embedded(one_primitive(
                                         R"("attributes": {"POSITION": )" + std::to_string(p) +
                                         R"(}, "indices": )" + std::to_string(i)))}},
                     "<dir>/house.gltf: node 'roof' (0), mesh 'tiles' (0), primitive 0: indices "
                     "accessor 1 element 2 is 3, beyond the 3 vertices of POSITION accessor 0"});
  }
  {
    GltfBuilder b;
    const int view = b.view(float_bytes({0, 0, 0, 1, 0, 0, 0, INFINITY, 0}));
    const int p = b.accessor(view, R"("componentType": 5126, "count": 3, "type": "VEC3")");
    cases.push_back(
        {"infinite_position",
         "house.gltf",
         {{"house.gltf", b.gltf_embedded(one_primitive(R"("attributes": {"POSITION": )" +
                                                       std::to_string(p) + "}"))}},
         "<dir>/house.gltf: node 'roof' (0), mesh 'tiles' (0), primitive 0: POSITION "
         "accessor 0 element 2 is not finite: (0, inf, 0)"});
  }
  {
    GltfBuilder b;
    const int view = b.view(float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0}));
    const int p = b.accessor(view, R"("componentType": 5126, "count": 3, "byteOffset": 4,
                                      "type": "VEC3")");
    cases.push_back(
        {"accessor_outside_its_view",
         "house.gltf",
         {{"house.gltf", b.gltf_embedded(one_primitive(R"("attributes": {"POSITION": )" +
                                                       std::to_string(p) + "}"))}},
         "<dir>/house.gltf: node 'roof' (0), mesh 'tiles' (0), primitive 0: POSITION "
         "accessor 0 (bytes 4 to 4 + 36) lies outside buffer view 0 of 36 bytes"});
  }
  {
    GltfBuilder b;
    const int p = b.positions(kTriangle);
    cases.push_back({"node_cycle",
                     "house.gltf",
                     {{"house.gltf", b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [
                         {"name": "a", "children": [1]}, {"name": "b", "children": [0], "mesh": 0}],
                         "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                                                     std::to_string(p) + "}}]}]")}},
                     "<dir>/house.gltf: node 'a' (0) is reached twice, from scene 0 and from "
                     "node 'b' (1): glTF's nodes form disjoint trees"});
  }
  return cases;
}

class GltfCli : public CliFolderTest<::testing::TestWithParam<BadModel>> {
 protected:
  GltfCli() : CliFolderTest("shadowgen-gltf-cli") {}
};

TEST_P(GltfCli, ExitsOneNamingTheModelAndLeavesNoOutput) {
  const BadModel& c = GetParam();
  const fs::path scene = write("scene.json", scene_naming(c.file_name));
  for (const auto& [path, bytes] : c.files) write(path, bytes);
  const Outcome outcome = run({"generate", scene.string(), "-o", (dir_ / "out.json").string()});
  EXPECT_EQ(outcome.code, 1) << outcome.err;
  EXPECT_EQ(outcome.out, "");
  std::string err = outcome.err;
  for (std::size_t at; (at = err.find(dir_.string())) != std::string::npos;) {
    err.replace(at, dir_.string().size(), "<dir>");
  }
  EXPECT_EQ(err, "shadowgen: " + c.message + "\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.json"));
}

INSTANTIATE_TEST_SUITE_P(Models, GltfCli, ::testing::ValuesIn(bad_models()),
                         [](const ::testing::TestParamInfo<BadModel>& param) {
                           return std::string(param.param.name);
                         });

class GltfReport : public CliFolderTest<> {
 protected:
  GltfReport() : CliFolderTest("shadowgen-gltf-report") {}
};

// A tile 2 m above a ground square, both in one .glb: the report names each triangle by
// its node, and the sun's shadow of the tile takes its area off the ground.
TEST_F(GltfReport, ReportNamesFacesByNode) {
  GltfBuilder b;
  const int ground = b.positions({{-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}});
  const int tile = b.positions({{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {0, 0, -1}});
  const int quad = b.indices({0, 1, 2, 0, 2, 3});
  write("house.glb",
        b.glb(R"("scenes": [{"nodes": [0, 1]}], "nodes": [{"name": "ground", "mesh": 0},
          {"name": "tile", "mesh": 1, "translation": [0, 2, 0]}],
          "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
              std::to_string(ground) + R"(}, "indices": )" + std::to_string(quad) +
              R"(}]}, {"primitives": [{"attributes": {"POSITION": )" + std::to_string(tile) +
              R"(}, "indices": )" + std::to_string(quad) + "}]}]"));
  const fs::path scene = write("scene.json", scene_naming("house.glb"));
  const Outcome outcome = run({"report", scene.string()});
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  const std::vector<ReportRow> rows = parse_report(outcome.out);
  std::vector<std::string> faces;
  double ground_lit = 0.0;
  for (const ReportRow& row : rows) {
    faces.push_back(row.face);
    if (row.face.starts_with("house/ground/")) ground_lit += row.lit_area;
  }
  EXPECT_EQ(faces, (std::vector<std::string>{"house/ground/0", "house/ground/1", "house/tile/0",
                                             "house/tile/1"}));
  EXPECT_NEAR(ground_lit, 100.0 - 1.0, 1e-9);  // the tile's 1 m² shadow, wholly on the ground
}

}  // namespace
}  // namespace shadowgen::test
