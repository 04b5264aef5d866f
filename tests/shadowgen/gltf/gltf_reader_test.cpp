// Tests of the glTF reader (shadowgen/gltf/gltf_reader.h) on files written here from the
// glTF 2.0 specification: placement through the node hierarchy and the turn from +y up to
// +z up against hand-computed vertices, mirrored nodes keeping their front side,
// instancing, strips and fans, ids, and the message for each kind of bad input.

#include "shadowgen/gltf/gltf_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gltf_builder.h"
#include "hsr/polygon3.h"
#include "shadowgen/model/input_error.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

namespace fs = std::filesystem;
using test::GltfBuilder;

const test::TempFolder& folder() {
  static const test::TempFolder temp("shadowgen-gltf-reader");
  return temp;
}

SourceModel read(const std::string& name, const std::string& content) {
  return gltf::read_gltf(folder().write(name, content), {});
}

// The message read_gltf refuses `content` with, the folder's path cut to "<dir>".
std::string refusal(const std::string& name, const std::string& content) {
  try {
    read(name, content);
  } catch (const InputError& e) {
    std::string what = e.what();
    const std::string dir = folder().path().string();
    for (std::size_t at; (at = what.find(dir)) != std::string::npos;)
      what.replace(at, dir.size(), "<dir>");
    return what;
  }
  return "(read without an error)";
}

void expect_point(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 0.0) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

void expect_triangle(const SourceFace& face, const std::vector<glm::dvec3>& corners,
                     double tolerance = 0.0) {
  ASSERT_EQ(face.polygon.outer.size(), 3u) << face.id;
  for (std::size_t i = 0; i < 3; ++i) expect_point(face.polygon.outer[i], corners[i], tolerance);
  EXPECT_TRUE(face.polygon.holes.empty());
}

glm::dvec3 unit_normal(const SourceFace& face) {
  const glm::dvec3 n = hsr::newell_vector(face.polygon.outer);
  return n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
}

// One triangle in glTF's xy plane, counter-clockwise seen from +z (its front side).
const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
// The same in the scene: (x, y, z) -> (x, -z, y), front side toward -y.
const std::vector<glm::dvec3> kTriangleZUp = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};

std::string one_node(const std::string& node_members, int mesh_members_position,
                     const std::string& mesh_name = "") {
  return R"("scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{)" + node_members +
         (node_members.empty() ? "" : ", ") + R"("mesh": 0}], "meshes": [{)" +
         (mesh_name.empty() ? "" : "\"name\": \"" + mesh_name + "\", ") +
         R"("primitives": [{"attributes": {"POSITION": )" + std::to_string(mesh_members_position) +
         "}}]}]";
}

TEST(GltfReader, EmbeddedBufferTurnsYUpToZUp) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const SourceModel model = read("embedded.gltf", b.gltf_embedded(one_node("", positions)));
  ASSERT_EQ(model.faces.size(), 1u);
  const SourceFace& face = model.faces[0];
  EXPECT_EQ(face.id, "0/0");
  EXPECT_EQ(face.origin, (FaceOrigin{"gltf", "0", "", ""}));
  EXPECT_EQ(face.described, "node 0 triangle 0");
  expect_triangle(face, kTriangleZUp);
  expect_point(unit_normal(face), {0, -1, 0});
  // |(1, 0, 0)|·2^-24 (with the 2^-150 floor of the zeros) through an identity of
  // Frobenius norm √3.
  EXPECT_NEAR(face.vertex_rounding, std::sqrt(3.0) * std::ldexp(1.0, -24), 1e-22);
  EXPECT_TRUE(model.warnings.empty());
  EXPECT_TRUE(model.site.empty());
}

TEST(GltfReader, ExternalBufferFileNamedNodeAndMesh) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  folder().write("roof.bin", b.buffer());
  const SourceModel model =
      read("external.gltf",
           b.gltf_external(one_node(R"("name": "roof")", positions, "tiles"), "roof.bin"));
  ASSERT_EQ(model.faces.size(), 1u);
  EXPECT_EQ(model.faces[0].id, "roof/0");
  EXPECT_EQ(model.faces[0].origin, (FaceOrigin{"gltf", "roof", "tiles", ""}));
  EXPECT_EQ(model.faces[0].described, "node 'roof' (0) triangle 0");
  expect_triangle(model.faces[0], kTriangleZUp);
}

TEST(GltfReader, BinaryFileReadsAsItsText) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const SourceModel model = read("binary.glb", b.glb(one_node(R"("name": "roof")", positions)));
  ASSERT_EQ(model.faces.size(), 1u);
  EXPECT_EQ(model.faces[0].id, "roof/0");
  expect_triangle(model.faces[0], kTriangleZUp);
}

// A parent of translation (10, 0, 0), rotation 90° about +y ((x, y, z) -> (z, y, -x)) and
// scale 2, over a child whose column-major matrix translates by (0, 1, 0):
// v -> (10, 0, 0) + R(2 (v + (0, 1, 0))), then (x, y, z) -> (x, -z, y):
//   (1, 0, 0) -> (1, 1, 0) -> (2, 2, 0) -> (0, 2, -2) -> (10, 2, -2) -> (10, 2, 2)
//   (0, 0, 0) -> (0, 1, 0) -> (0, 2, 0) -> (0, 2, 0)  -> (10, 2, 0)  -> (10, 0, 2)
//   (0, 0, 1) -> (0, 1, 1) -> (0, 2, 2) -> (2, 2, 0)  -> (12, 2, 0)  -> (12, 0, 2)
TEST(GltfReader, NodeHierarchyWithTrsAndMatrix) {
  GltfBuilder b;
  const int positions = b.positions({{1, 0, 0}, {0, 0, 0}, {0, 0, 1}});
  const std::string members =
      R"("scenes": [{"nodes": [0]}], "nodes": [
        {"name": "parent", "translation": [10, 0, 0], "scale": [2, 2, 2],
         "rotation": [0, 0.7071067811865476, 0, 0.7071067811865476], "children": [1]},
        {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1], "mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
      std::to_string(positions) + "}}]}]";
  const SourceModel model = read("hierarchy.gltf", b.gltf_embedded(members));
  ASSERT_EQ(model.faces.size(), 1u);
  EXPECT_EQ(model.faces[0].id, "1/0");
  expect_triangle(model.faces[0], {{10, 2, 2}, {10, 0, 2}, {12, 0, 2}}, 1e-14);
  // Scale 2 on every axis: the linear part's Frobenius norm is 2√3; the largest vertex
  // of the mesh has length 1.
  EXPECT_NEAR(model.faces[0].vertex_rounding, 2 * std::sqrt(3.0) * std::ldexp(1.0, -24), 1e-20);
}

// Scale -1 along x mirrors the triangle; its corners are taken in reverse so that its
// front side stays the side its front was on: glTF's +z, the scene's -y.
TEST(GltfReader, MirroredNodeKeepsTheFrontSide) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const SourceModel model =
      read("mirrored.gltf", b.gltf_embedded(one_node(R"("scale": [-1, 1, 1])", positions)));
  ASSERT_EQ(model.faces.size(), 1u);
  expect_triangle(model.faces[0], {{0, 0, 0}, {0, 0, 1}, {-1, 0, 0}});
  expect_point(unit_normal(model.faces[0]), {0, -1, 0});
}

TEST(GltfReader, MeshOfTwoNodesGivesEachNodeItsFaces) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const std::string members =
      R"("scenes": [{"nodes": [0, 1]}], "nodes": [
        {"name": "a", "mesh": 0}, {"name": "b", "translation": [5, 0, 0], "mesh": 0}],
      "meshes": [{"name": "shed", "primitives": [{"attributes": {"POSITION": )" +
      std::to_string(positions) + "}}]}]";
  const SourceModel model = read("instanced.gltf", b.gltf_embedded(members));
  ASSERT_EQ(model.faces.size(), 2u);
  EXPECT_EQ(model.faces[0].id, "a/0");
  EXPECT_EQ(model.faces[1].id, "b/0");
  EXPECT_EQ(model.faces[1].origin, (FaceOrigin{"gltf", "b", "shed", ""}));
  expect_triangle(model.faces[0], kTriangleZUp);
  expect_triangle(model.faces[1], {{5, 0, 0}, {6, 0, 0}, {5, 0, 1}});
}

// A strip and a fan of five vertices in glTF's xy plane, their first triangles
// counter-clockwise seen from +z: every triangle keeps the first's winding, so every
// normal is the scene's -y. Triangles are numbered on over the node's primitives.
TEST(GltfReader, StripsAndFansBecomeTheirTriangles) {
  GltfBuilder b;
  // A strip zigzagging along x: 0 (0,1) 1 (0,0) 2 (1,1) 3 (1,0) 4 (2,1).
  const int strip = b.positions({{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {2, 1, 0}});
  // A fan around the origin: 0 (0,0) then 1 (2,0) 2 (2,1) 3 (1,2) 4 (0,2).
  const int fan = b.positions({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 2, 0}});
  const int triangles = b.positions(kTriangle);
  const std::string members =
      R"("scenes": [{"nodes": [0]}], "nodes": [{"name": "n", "mesh": 0}],
      "meshes": [{"primitives": [
        {"attributes": {"POSITION": )" +
      std::to_string(triangles) + R"(}, "mode": 4},
        {"attributes": {"POSITION": )" +
      std::to_string(strip) + R"(}, "mode": 5},
        {"attributes": {"POSITION": )" +
      std::to_string(fan) + R"(}, "mode": 6}]}])";
  const SourceModel model = read("strips.gltf", b.gltf_embedded(members));
  ASSERT_EQ(model.faces.size(), 7u);
  for (std::size_t k = 0; k < 7; ++k) {
    EXPECT_EQ(model.faces[k].id, "n/" + std::to_string(k));
    expect_point(unit_normal(model.faces[k]), {0, -1, 0}, 1e-15);
  }
  // Strip p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)}: {0,1,2}, {1,3,2}, {2,3,4}.
  expect_triangle(model.faces[1], {{0, 0, 1}, {0, 0, 0}, {1, 0, 1}});
  expect_triangle(model.faces[2], {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}});
  expect_triangle(model.faces[3], {{1, 0, 1}, {1, 0, 0}, {2, 0, 1}});
  // Fan p_i = {v_i+1, v_i+2, v_0}: {1,2,0}, {2,3,0}, {3,4,0}.
  expect_triangle(model.faces[4], {{2, 0, 0}, {2, 0, 1}, {0, 0, 0}});
  expect_triangle(model.faces[5], {{2, 0, 1}, {1, 0, 2}, {0, 0, 0}});
  expect_triangle(model.faces[6], {{1, 0, 2}, {0, 0, 2}, {0, 0, 0}});
}

TEST(GltfReader, IndexedStridedAndSparseAccessors) {
  GltfBuilder b;
  // Interleaved position and normal, 24 bytes a vertex; vertex 3 is never indexed.
  const int interleaved = b.view(test::float_bytes({0, 0, 0, 0, 0, 1,  //
                                                    7, 7, 7, 0, 0, 1,  //
                                                    0, 1, 0, 0, 0, 1,  //
                                                    9, 9, 9, 0, 0, 1}),
                                 24);
  // Sparse: vertex 1 becomes (1, 0, 0).
  const int sparse_indices = b.view(test::u16_bytes({1, 0}));
  const int sparse_values = b.view(test::float_bytes({1, 0, 0}));
  const int positions = b.accessor(
      interleaved, R"("componentType": 5126, "count": 4, "type": "VEC3", "sparse": {"count": 1,
        "indices": {"bufferView": )" +
                       std::to_string(sparse_indices) +
                       R"(, "componentType": 5123}, "values": {"bufferView": )" +
                       std::to_string(sparse_values) + "}}");
  const int indices = b.indices({0, 1, 2});
  const std::string members =
      R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}], "meshes": [{"primitives": [
        {"attributes": {"POSITION": )" +
      std::to_string(positions) + R"(}, "indices": )" + std::to_string(indices) + "}]}]";
  const SourceModel model = read("sparse.gltf", b.gltf_embedded(members));
  ASSERT_EQ(model.faces.size(), 1u);
  expect_triangle(model.faces[0], kTriangleZUp);
}

TEST(GltfReader, QuantizedPositionsWithTheirExtension) {
  GltfBuilder b;
  const int view = b.view(test::u16_bytes({0, 0, 0, 65535, 0, 0, 0, 65535, 0, 0}));
  const int positions =
      b.accessor(view, R"("componentType": 5123, "normalized": true, "count": 3, "type": "VEC3")");
  const std::string mesh = one_node(R"("scale": [4, 4, 4])", positions);
  const SourceModel model =
      read("quantized.gltf", b.gltf_embedded(R"("extensionsUsed": ["KHR_mesh_quantization"],
                         "extensionsRequired": ["KHR_mesh_quantization"], )" +
                                             mesh));
  ASSERT_EQ(model.faces.size(), 1u);
  expect_triangle(model.faces[0], {{0, 0, 0}, {4, 0, 0}, {0, 0, 4}});
  // Half a step of 1/65535 on each of three components, through 4·√3.
  EXPECT_NEAR(model.faces[0].vertex_rounding, 4 * std::sqrt(3.0) * std::sqrt(3.0) * 0.5 / 65535,
              1e-18);
  EXPECT_EQ(refusal("unquantized.gltf", b.gltf_embedded(mesh)),
            "<dir>/unquantized.gltf: node 0, mesh 0, primitive 0: POSITION accessor 0 has "
            "components of type UNSIGNED_SHORT: glTF 2.0 positions are FLOAT, integers only "
            "with KHR_mesh_quantization, which the file does not use");
}

TEST(GltfReader, NodesSharingANameAreToldApartByIndex) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const std::string mesh = R"("meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                           std::to_string(positions) + "}}]}]";
  const SourceModel model =
      read("names.gltf", b.gltf_embedded(R"("scenes": [{"nodes": [0, 1, 2]}], "nodes": [
        {"name": "wall", "mesh": 0}, {"name": "wall", "mesh": 0}, {"mesh": 0}], )" +
                                         mesh));
  ASSERT_EQ(model.faces.size(), 3u);
  EXPECT_EQ(model.faces[0].id, "wall/0");
  EXPECT_EQ(model.faces[1].id, "wall#1/0");
  EXPECT_EQ(model.faces[1].origin.object, "wall");
  EXPECT_EQ(model.faces[2].id, "2/0");
  EXPECT_EQ(refusal("taken.gltf", b.gltf_embedded(R"("scenes": [{"nodes": [0, 1, 2]}], "nodes": [
        {"name": "wall#2", "mesh": 0}, {"name": "wall", "mesh": 0}, {"name": "wall", "mesh": 0}], )" +
                                                  mesh)),
            "<dir>/taken.gltf: node 'wall' (2) shares its name with an earlier node, and node "
            "'wall#2' (0) already has the label 'wall#2' that would tell it apart");
}

TEST(GltfReader, MorphTargetsAndSkinsAreIgnoredWithAWarning) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const int offsets = b.positions({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
  const SourceModel model =
      read("morph.gltf",
           b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "skin": 0}],
        "skins": [{"joints": [0]}],
        "meshes": [{"weights": [1], "primitives": [{"attributes": {"POSITION": )" +
                           std::to_string(positions) + R"(}, "targets": [{"POSITION": )" +
                           std::to_string(offsets) + "}]}]}]"));
  ASSERT_EQ(model.faces.size(), 1u);
  expect_triangle(model.faces[0], kTriangleZUp);
  ASSERT_EQ(model.warnings.size(), 2u);
  const std::string file = (folder().path() / "morph.gltf").string();
  EXPECT_EQ(model.warnings[0], file +
                                   ": node 0: its skin is not applied: the mesh is read "
                                   "unskinned, at the node's transform");
  EXPECT_EQ(model.warnings[1], file +
                                   ": node 0, mesh 0, primitive 0: morph targets are not "
                                   "applied: the base positions are read");
}

// More than three primitives without positions: one line, how many and the first three.
TEST(GltfReader, AKindOfWarningOfManyIsOneLine) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const std::string empty = R"({"attributes": {"NORMAL": )" + std::to_string(positions) + "}}";
  const SourceModel model =
      read("many.gltf", b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                                        std::to_string(positions) + "}}, " + empty + ", " + empty +
                                        ", " + empty + ", " + empty + "]}]"));
  ASSERT_EQ(model.faces.size(), 1u);
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_EQ(model.warnings[0], (folder().path() / "many.gltf").string() +
                                   ": 4 primitives: no POSITION attribute: the primitive draws "
                                   "nothing and is skipped: node 0, mesh 0, primitive 1; node 0, "
                                   "mesh 0, primitive 2; node 0, mesh 0, primitive 3; ...");
}

// Images serve materials only: a missing image file, a folder or a device named as one,
// and an image in a buffer view that is no picture are not read, and draw no word.
TEST(GltfReader, ImagesAreNeverRead) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const int junk = b.view("not a picture");
  const SourceModel model =
      read("images.gltf",
           b.gltf_embedded(one_node("", positions) + R"(, "images": [{"uri": "missing.png"},
        {"uri": "/dev/zero"}, {"uri": "."}, {"bufferView": )" +
                           std::to_string(junk) + R"(, "mimeType": "image/png"}])"));
  ASSERT_EQ(model.faces.size(), 1u);
  EXPECT_TRUE(model.warnings.empty());
}

// ---- Bad input ---------------------------------------------------------------------------

TEST(GltfReaderErrors, MissingBufferFile) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  EXPECT_EQ(refusal("lost.gltf", b.gltf_external(one_node("", positions), "lost.bin")),
            "<dir>/lost.gltf: buffers[0]: file <dir>/lost.bin: no such file");
}

// tinygltf looks for a buffer file in the working folder when it is not next to the glTF
// file; shadowgen looks next to the glTF file only.
TEST(GltfReaderErrors, BufferFileOnlyNextToTheGltfFile) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  folder().write("stray.bin", b.buffer());
  fs::create_directories(folder().path() / "sub");
  const fs::path gltf =
      folder().write("sub/stray.gltf", b.gltf_external(one_node("", positions), "stray.bin"));
  const fs::path before = fs::current_path();
  fs::current_path(folder().path());
  std::string message;
  try {
    gltf::read_gltf(gltf, {});
  } catch (const InputError& e) {
    message = e.what();
  }
  fs::current_path(before);
  EXPECT_EQ(message, gltf.string() + ": buffers[0]: file " +
                         (folder().path() / "sub" / "stray.bin").string() + ": no such file");
}

TEST(GltfReaderErrors, DataUriOfAnotherKind) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  EXPECT_EQ(refusal("datauri.gltf",
                    b.json(one_node("", positions), R"("uri": "data:model/unknown,AAAA")")),
            "<dir>/datauri.gltf: buffers[0].uri: a data: URI of a buffer is base64, of media type "
            "application/octet-stream or application/gltf-buffer (the specification's), which "
            "this one is not");
}

TEST(GltfReaderErrors, BufferFileOfAnotherSize) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  folder().write("short.bin", b.buffer().substr(0, 30));
  EXPECT_EQ(refusal("short.gltf", b.gltf_external(one_node("", positions), "short.bin")),
            "<dir>/short.gltf: buffers[0]: file <dir>/short.bin has 30 bytes, fewer than the "
            "buffer's byteLength of 36");
  // More bytes than byteLength: the specification allows it, the buffer is the first ones.
  folder().write("long.bin", b.buffer() + "more");
  EXPECT_EQ(read("long.gltf", b.gltf_external(one_node("", positions), "long.bin")).faces.size(),
            1u);
}

TEST(GltfReaderErrors, TruncatedGlb) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const std::string whole = b.glb(one_node("", positions));
  const std::string cut = whole.substr(0, whole.size() - 8);
  EXPECT_EQ(refusal("cut.glb", cut),
            "<dir>/cut.glb: not a well-formed binary glTF file: is truncated: its header gives "
            "a length of " +
                std::to_string(whole.size()) + " bytes, the file has " +
                std::to_string(cut.size()));
  EXPECT_EQ(refusal("header.glb", whole.substr(0, 10)),
            "<dir>/header.glb: not a well-formed binary glTF file: is truncated: 10 bytes, "
            "fewer than the 20 of its header and first chunk header");
}

TEST(GltfReaderErrors, AccessorOutsideItsBufferView) {
  GltfBuilder b;
  const int view = b.view(test::float_bytes({0, 0, 0, 1, 0, 0, 0, 1, 0}));
  const int positions = b.accessor(view, R"("componentType": 5126, "count": 4, "type": "VEC3")");
  EXPECT_EQ(refusal("outside.gltf", b.gltf_embedded(one_node("", positions))),
            "<dir>/outside.gltf: node 0, mesh 0, primitive 0: POSITION accessor 0 (bytes 0 to "
            "0 + 48) lies outside buffer view 0 of 36 bytes");
}

TEST(GltfReaderErrors, BufferViewOutsideItsBuffer) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  std::string text = b.gltf_embedded(one_node("", positions));
  const std::string view = R"("byteOffset": 0, "byteLength": 36)";
  text.replace(text.find(view), view.size(), R"("byteOffset": 4, "byteLength": 36)");
  EXPECT_EQ(refusal("view.gltf", text),
            "<dir>/view.gltf: node 0, mesh 0, primitive 0: buffer view 0 (bytes 4 to 4 + 36) "
            "lies outside buffer 0 of 36 bytes");
}

TEST(GltfReaderErrors, IndexOutOfRange) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const int indices = b.indices({0, 1, 5});
  EXPECT_EQ(
      refusal("index.gltf", b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
                      "meshes": [{"name": "m", "primitives": [{"attributes": {"POSITION": )" +
                                            std::to_string(positions) + R"(}, "indices": )" +
                                            std::to_string(indices) + "}]}]")),
      "<dir>/index.gltf: node 0, mesh 'm' (0), primitive 0: indices accessor 1 element 2 "
      "is 5, beyond the 3 vertices of POSITION accessor 0");
}

TEST(GltfReaderErrors, NonFinitePosition) {
  GltfBuilder b;
  const int view = b.view(test::float_bytes({0, 0, 0, NAN, 0, 0, 0, 1, 0}));
  const int positions = b.accessor(view, R"("componentType": 5126, "count": 3, "type": "VEC3")");
  EXPECT_EQ(refusal("nan.gltf", b.gltf_embedded(one_node(R"("name": "n")", positions))),
            "<dir>/nan.gltf: node 'n' (0), mesh 0, primitive 0: POSITION accessor 0 element 1 "
            "is not finite: (nan, 0, 0)");
}

TEST(GltfReaderErrors, RequiredCompression) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  EXPECT_EQ(
      refusal("draco.gltf", b.gltf_embedded(R"("extensionsUsed": ["KHR_draco_mesh_compression"],
                      "extensionsRequired": ["KHR_draco_mesh_compression"], )" +
                                            one_node("", positions))),
      "<dir>/draco.gltf: extensionsRequired[0]: the file requires "
      "'KHR_draco_mesh_compression' (Draco-compressed meshes), which shadowgen does not "
      "read");
  EXPECT_EQ(
      refusal(
          "meshopt.glb",
          b.glb(R"("extensionsRequired": ["KHR_materials_unlit", "EXT_meshopt_compression"], )" +
                one_node("", positions))),
      "<dir>/meshopt.glb: extensionsRequired[1]: the file requires "
      "'EXT_meshopt_compression' (meshoptimizer-compressed buffers), which shadowgen does "
      "not read");
}

// Draco used but not required: a primitive with an uncompressed fallback is read from it;
// one without (its positions' accessor has no buffer view) is refused.
TEST(GltfReaderErrors, DracoPrimitiveWithoutFallback) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const int compressed = b.accessor(-1, R"("componentType": 5126, "count": 3, "type": "VEC3")");
  const std::string draco =
      R"("extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}})";
  auto file = [&](int accessor) {
    return b.gltf_embedded(R"("extensionsUsed": ["KHR_draco_mesh_compression"],
      "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                           std::to_string(accessor) + "}, " + draco + "}]}]");
  };
  EXPECT_EQ(read("fallback.gltf", file(positions)).faces.size(), 1u);
  EXPECT_EQ(refusal("draco.gltf", file(compressed)),
            "<dir>/draco.gltf: node 0, mesh 0, primitive 0: its positions are Draco-compressed "
            "(KHR_draco_mesh_compression), which shadowgen does not read");
}

TEST(GltfReaderErrors, PointsAndLines) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  EXPECT_EQ(
      refusal("lines.gltf",
              b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [{"name": "rail", "mesh": 0}],
                      "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                              std::to_string(positions) + R"(}, "mode": 1}]}])")),
      "<dir>/lines.gltf: node 'rail' (0), mesh 0, primitive 0: mode 1 (LINES) draws no "
      "faces: shadowgen reads TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN");
}

// tinygltf reads an absent index as -1; any other negative one is an index out of range.
TEST(GltfReaderErrors, NegativeIndices) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const std::string mesh = R"("meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                           std::to_string(positions) + "}, \"indices\": -2}]}]";
  EXPECT_EQ(
      refusal("negative.gltf",
              b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": -2}], )" + mesh)),
      "<dir>/negative.gltf: node 0 names mesh -2, of 1");
  EXPECT_EQ(
      refusal("negative.gltf",
              b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}], )" + mesh)),
      "<dir>/negative.gltf: node 0, mesh 0, primitive 0: indices names accessor -2, of 1");
  EXPECT_EQ(refusal("negative.gltf",
                    b.gltf_embedded(R"("scene": -3, "scenes": [{"nodes": [0]}], "nodes": [{}])")),
            "<dir>/negative.gltf: 'scene' is -3, of 1 scenes");
}

TEST(GltfReaderErrors, NodeCycle) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  EXPECT_EQ(refusal("cycle.gltf", b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [
                      {"children": [1]}, {"children": [0], "mesh": 0}],
                      "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                                                  std::to_string(positions) + "}}]}]")),
            "<dir>/cycle.gltf: node 0 is reached twice, from scene 0 and from node 1: glTF's "
            "nodes form disjoint trees");
}

TEST(GltfReaderErrors, NotGltfTwoJson) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  std::string text = b.gltf_embedded(one_node("", positions));
  EXPECT_EQ(refusal("twice.gltf", R"({"asset": {"version": "2.0", "version": "2.0"}})"),
            "<dir>/twice.gltf: asset: the key 'version' is given twice (a key may appear once "
            "in an object)");
  EXPECT_EQ(refusal("old.gltf", R"({"asset": {"version": "1.0"}})"),
            "<dir>/old.gltf: asset.version: '1.0': shadowgen reads glTF 2.0");
  EXPECT_EQ(
      refusal(
          "noscene.gltf",
          b.json(
              R"("nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}])",
              "\"uri\": \"data:application/octet-stream;base64," + test::base64(b.buffer()) +
                  "\"")),
      "<dir>/noscene.gltf: has no scene: a glTF file without scenes places no node");
  // glTF allows an integer written 3.0; tinygltf, and so shadowgen, reads JSON integers only.
  std::string fraction = b.gltf_embedded(one_node("", positions));
  const std::string count = "\"count\": 3,";
  fraction.replace(fraction.find(count), count.size(), "\"count\": 3.0,");
  EXPECT_EQ(refusal("fraction.gltf", fraction),
            "<dir>/fraction.gltf: not a readable glTF file: 'count' property is not a positive "
            "integer.");
}

TEST(GltfReaderErrors, ZerosWithoutEnd) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const int zeros = b.accessor(-1, R"("componentType": 5126, "count": 3000000000, "type": "VEC3")");
  EXPECT_EQ(
      refusal("zeros.gltf",
              b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
                      "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
                              std::to_string(positions) + R"(}}, {"attributes": {"POSITION": )" +
                              std::to_string(zeros) + "}}]}]")),
      "<dir>/zeros.gltf: node 0, mesh 0, primitive 1: POSITION accessor 1 has no buffer "
      "view and 3000000000 elements, more than the 36 bytes of the file's buffers: they "
      "would be zeros made up");
}

// Nothing crashes on a damaged file: a .glb cut at every length, and with every byte
// changed in turn, is read or refused with an InputError, never anything else.
TEST(GltfReaderErrors, DamagedGlbIsReadOrRefused) {
  GltfBuilder b;
  const int positions = b.positions(kTriangle);
  const int indices = b.indices({0, 1, 2});
  const std::string whole = b.glb(
      R"("scenes": [{"nodes": [0]}], "nodes": [{"children": [1]}, {"mesh": 0, "scale": [1, 2, 3]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": )" +
      std::to_string(positions) + R"(}, "indices": )" + std::to_string(indices) + "}]}]");
  const fs::path path = folder().path() / "damaged.glb";
  std::size_t read = 0, refused = 0;
  auto attempt = [&](const std::string& bytes) {
    folder().write("damaged.glb", bytes);
    try {
      gltf::read_gltf(path, {});
      ++read;
    } catch (const InputError&) {
      ++refused;
    }
  };
  for (std::size_t length = 0; length < whole.size(); ++length) attempt(whole.substr(0, length));
  for (std::size_t at = 0; at < whole.size(); ++at) {
    for (const int value : {0x00, 0xff, int{'9'}, int{']'}}) {
      std::string bytes = whole;
      bytes[at] = static_cast<char>(value);
      attempt(bytes);
    }
  }
  EXPECT_EQ(read + refused, whole.size() * 5);
  EXPECT_GT(refused, whole.size());  // every cut one at least
}

}  // namespace
}  // namespace shadowgen
