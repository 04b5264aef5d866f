// Tests of the mesh readers (shadowgen/scene/detail/mesh_reader.h and the readers behind
// it) and of pinched and bridged loops (loop_validation.h): the scene format's reading
// rule that a file that is not a readable mesh of its format is an error, with nothing
// made up and nothing dropped, and its rule that a loop passing through one vertex twice
// without crossing stands for the region it bounds, downstream included (triangulation
// of non-planar faces, shadows).

#include "shadowgen/scene/detail/mesh_reader.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "clipper/polygon.h"
#include "hsr/area.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/scene/detail/loop_validation.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {
namespace {

namespace fs = std::filesystem;

// ---- Fixtures --------------------------------------------------------------------------

// A fresh temporary folder, removed with everything in it at the end of the test run.
const fs::path& temp_dir() {
  static const fs::path dir = [] {
    std::string pattern = (fs::temp_directory_path() / "shadowgen-mesh-reader-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    return fs::path(pattern);
  }();
  return dir;
}

class RemoveTempDir : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code error;
    fs::remove_all(temp_dir(), error);
  }
};
const auto* const remove_temp_dir = ::testing::AddGlobalTestEnvironment(new RemoveTempDir);

fs::path write(const std::string& name, const std::string& bytes) {
  const fs::path path = temp_dir() / name;
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  out.close();
  EXPECT_TRUE(out.good()) << path;
  return path;
}

scene::detail::MeshSoup read(const std::string& name, const std::string& bytes) {
  return scene::detail::read_mesh(write(name, bytes), "m");
}

// The InputError reading `bytes` as `name` gives; a failure when there is none.
InputError read_error(const std::string& name, const std::string& bytes) {
  try {
    const scene::detail::MeshSoup soup = read(name, bytes);
    ADD_FAILURE() << name << ": read without an error, " << soup.vertices.size() << " vertices, "
                  << soup.faces.size() << " faces";
  } catch (const InputError& e) {
    return e;
  }
  return InputError("", "", "");
}

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

// The problem names the mesh file.
void ExpectNamesFile(const InputError& e, const std::string& name) {
  EXPECT_EQ(fs::path(e.file()).filename(), name) << e.what();
}

std::vector<std::int64_t> indices(std::initializer_list<std::int64_t> list) { return list; }

// Little- and big-endian binary data.
struct Bytes {
  std::string data;
  Bytes& raw(const std::string& s) {
    data += s;
    return *this;
  }
  Bytes& u(std::uint64_t v, int size, bool big = false) {
    for (int i = 0; i < size; ++i) {
      const int shift = 8 * (big ? size - 1 - i : i);
      data += static_cast<char>((v >> shift) & 0xFF);
    }
    return *this;
  }
  Bytes& f32(float v, bool big = false) { return u(std::bit_cast<std::uint32_t>(v), 4, big); }
  Bytes& f64(double v, bool big = false) { return u(std::bit_cast<std::uint64_t>(v), 8, big); }
};

// A scene with the mesh file `name` as mesh 'm', and `more` JSON members.
std::string scene_with_mesh(const std::string& name, const std::string& more = "") {
  return R"({"format": "shadowgen-scene/1", "meshes": [{"id": "m", "file": ")" + name + R"("}])" +
         more + "}";
}

ReadResult read_scene_with_mesh(const std::string& name, const std::string& bytes,
                                const std::string& more = "") {
  write(name, bytes);
  return parse_scene(scene_with_mesh(name, more), temp_dir() / "scene.json");
}

// ---- Every format: a file without faces ------------------------------------------------

TEST(MeshReader, AMeshWithoutFacesIsAnError) {
  for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
           {"vertices_only.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
           {"prose.obj", "This is not a mesh, just some text.\n"},
           {"empty.obj", ""},
           {"no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"},
           {"no_facets.stl", "solid empty\nendsolid empty\n"},
           {"no_faces.ply",
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
            "property float z\nelement face 0\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n"},
       }) {
    const InputError e = read_error(name, bytes);
    EXPECT_TRUE(Contains(e.problem(), "mesh 'm' has no faces")) << name;
    ExpectNamesFile(e, name);
  }
  Bytes zero_triangles;
  zero_triangles.raw(std::string(80, ' ')).u(0, 4);
  EXPECT_TRUE(Contains(read_error("zero.stl", zero_triangles.data).problem(), "has no faces"));
}

TEST(MeshReader, TheSceneRejectsAReferencedMeshWithoutFaces) {
  // It used to be a warning, and the scene was read (and generated: exit 0).
  try {
    read_scene_with_mesh("only_vertices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    ExpectNamesFile(e, "only_vertices.obj");
    EXPECT_TRUE(Contains(e.problem(), "has no faces"));
  }
}

// ---- OBJ -------------------------------------------------------------------------------

TEST(ObjReader, BinaryJunkIsNotAMesh) {
  std::string junk;
  for (int i = 0; i < 512; ++i) junk += static_cast<char>((i * 97 + 13) % 256);
  const InputError e = read_error("junk.obj", junk);
  EXPECT_TRUE(Contains(e.problem(), "not a text file"));
  ExpectNamesFile(e, "junk.obj");
}

TEST(ObjReader, Utf16TextIsNotAMesh) {
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::string utf16le = "\xFF\xFE";  // the byte order mark
  std::string utf16be = "\xFE\xFF";
  std::string no_mark;
  for (const char c : text) {
    utf16le += std::string{c, '\0'};
    utf16be += std::string{'\0', c};
    no_mark += std::string{c, '\0'};
  }
  for (const std::string& bytes : {utf16le, utf16be, no_mark}) {
    EXPECT_TRUE(Contains(read_error("utf16.obj", bytes).problem(), "not a text file (UTF-16?)"));
  }
}

TEST(ObjReader, ControlBytesAreNotText) {
  const InputError e = read_error("control.obj", "v 0 0 0\nv 1 0 0\x01\nv 0 1 0\nf 1 2 3\n");
  EXPECT_TRUE(Contains(e.problem(), "not a text file (binary?): control byte 0x01 on line 2"));
}

TEST(ObjReader, TextWithUtf8AndLatin1CommentsIsRead) {
  const scene::detail::MeshSoup soup =
      read("accents.obj",
           "\xEF\xBB\xBF# Cr\xC3\xA9\xC3\xA9 / cr\xE9\xE9\nv 0 0 0\nv 1 0 0\n"
           "v 0 1 0\f\nf 1 2 3\n");
  ASSERT_EQ(soup.faces.size(), 1u);
  EXPECT_EQ(soup.faces[0].vertices, indices({0, 1, 2}));
}

TEST(ObjReader, OldMacLineEndingsAreLines) {
  // A lone carriage return ends a line; read as one line, the first vertex would have
  // swallowed the rest of the file.
  const scene::detail::MeshSoup soup = read("mac.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
  ASSERT_EQ(soup.vertices.size(), 3u);
  ASSERT_EQ(soup.faces.size(), 1u);
  EXPECT_EQ(soup.faces[0].line, 4u);
  EXPECT_EQ(soup.vertices[2], glm::dvec3(0, 1, 0));
}

TEST(ObjReader, SomethingElseAfterAVertexIsAnError) {
  // Two vertices run together would lose the second.
  EXPECT_TRUE(Contains(read_error("joined.obj", "v 0 0 0 v 1 0 0\nf 1 1 1\n").problem(),
                       "line 1: 'v' after a vertex's coordinates is not a number"));
  EXPECT_TRUE(Contains(read_error("many.obj", "v 0 0 0 1 2 3 4 5\n").problem(), "at most"));
  // A weight, or a colour: fine.
  EXPECT_EQ(read("colour.obj", "v 0 0 0 1 0.5 0\nv 1 0 0 1\nv 0 1 0\nf 1 2 3\n").vertices.size(),
            3u);
}

// ---- STL -------------------------------------------------------------------------------

// A binary STL file whose 80-byte header begins with "solid", with `triangles` triangles
// announced and `present` written. Its bytes hold no line feed.
std::string binary_stl(std::uint32_t triangles, std::uint32_t present) {
  Bytes b;
  std::string header = "solid exported by a CAD program";
  header.resize(80, ' ');
  b.raw(header).u(triangles, 4);
  for (std::uint32_t t = 0; t < present; ++t) {
    b.f32(0).f32(0).f32(1);  // normal
    b.f32(static_cast<float>(t)).f32(0).f32(0);
    b.f32(static_cast<float>(t) + 1).f32(0).f32(0);
    b.f32(static_cast<float>(t)).f32(1).f32(0);
    b.u(0, 2);  // attribute byte count
  }
  return b.data;
}

TEST(StlReader, BinaryWithASolidHeaderIsBinary) {
  const scene::detail::MeshSoup soup = read("solid_header.stl", binary_stl(2, 2));
  ASSERT_EQ(soup.faces.size(), 2u);
  EXPECT_EQ(soup.vertices[4], glm::dvec3(2, 0, 0));
}

TEST(StlReader, TruncatedBinaryWithASolidHeaderIsAnError) {
  // Its size does not fit its count; it used to be read as ASCII, and its one long line,
  // beginning with "solid", gave an empty mesh.
  const InputError e = read_error("truncated.stl", binary_stl(3, 2));
  EXPECT_TRUE(Contains(e.problem(), "not an STL file: not a text file"));
  EXPECT_TRUE(Contains(e.problem(),
                       "does not match the 3 triangles its header announces (84 + "
                       "50 * 3 = 234 bytes; truncated?)"));
  ExpectNamesFile(e, "truncated.stl");
  EXPECT_TRUE(Contains(read_error("padded.stl", binary_stl(1, 2)).problem(),
                       "does not match the 1 triangles"));
}

TEST(StlReader, AsciiMustBeComplete) {
  const std::string facet =
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
      " endloop\nendfacet\n";
  EXPECT_EQ(read("one.stl", "solid a\n" + facet + "endsolid a\n").faces.size(), 1u);
  EXPECT_EQ(read("two.stl", "solid a\n" + facet + "endsolid a\nsolid b\n" + facet + "endsolid\n")
                .faces.size(),
            2u);
  EXPECT_TRUE(Contains(read_error("no_end.stl", "solid a\n" + facet).problem(),
                       "the file ends before 'endsolid' (truncated?)"));
  EXPECT_TRUE(
      Contains(read_error("no_loop.stl", "solid a\nfacet normal 0 0 1\nvertex 0 0 0\n").problem(),
               "line 3: 'vertex' outside a facet's 'outer loop'"));
}

// ---- OFF -------------------------------------------------------------------------------

TEST(OffReader, AHeaderAnnouncingMoreFacesThanFollowIsAnError) {
  // OpenMesh's reader made up the missing face as a copy of the last.
  const InputError e = read_error("short.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n");
  EXPECT_TRUE(Contains(e.problem(), "the file ends after 1 of the 2 faces its header announces"));
  ExpectNamesFile(e, "short.off");
  EXPECT_TRUE(Contains(read_error("short_v.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n").problem(),
                       "ends after 3 of the 4 vertices"));
  EXPECT_TRUE(Contains(
      read_error("long.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 2 1 0\n").problem(),
      "line 7: more data after the 3 vertices and 1 face the header announces"));
}

TEST(OffReader, MalformedRecordsAreErrors) {
  const std::string v = "0 0 0\n1 0 0\n0 1 0\n";
  for (const auto& [bytes, problem] : std::vector<std::pair<std::string, std::string>>{
           {"OFF\n-3 1 0\n", "the vertex count is negative"},
           {"OFF\n3 x 0\n", "the face count 'x' is not an integer"},
           {"OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "line 4: a vertex line here has 3"},
           {"OFF\n3 1 0\n0 0 0\n1 0 0 7\n0 1 0\n3 0 1 2\n", "this one has 4"},
           {"OFF\n3 1 0\n0 0 nan\n1 0 0\n0 1 0\n3 0 1 2\n", "coordinate 'nan' is not a finite"},
           {"OFF\n3 1 0\n0 0 1e999\n1 0 0\n0 1 0\n3 0 1 2\n", "'1e999' is not a finite"},
           {"OFF\n3 1 0\n" + v + "4 0 1 2\n", "the face announces 4 vertex indices but lists 3"},
           {"OFF\n3 1 0\n" + v + "3 0 1 x\n", "vertex index 'x' is not an integer"},
           {"OFF\n3 1 0\n" + v + "3 0 1 2 1 1 1 1 1\n", "5 numbers after its 3 vertex indices"},
           {"OFF\n3 1 0\n" + v + "-3 0 1 2\n", "is not a non-negative integer"},
           {"OFF 3 1 0 9\n", "unexpected '9' after the counts"},
           {"OFFSET\n", "not an OFF file"},
           {"nOFF\n4\n3 1 0\n", "only 3-dimensional OFF is read"},
           {"OFF\n", "the file ends in its header"},
       }) {
    EXPECT_TRUE(Contains(read_error("bad.off", bytes).problem(), problem)) << bytes;
  }
  // An index out of range is the scene reader's to report, with the face.
  try {
    read_scene_with_mesh("index.off", "OFF\n3 1 0\n" + v + "3 0 1 3\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.face_id(), "m/0");
    EXPECT_TRUE(Contains(e.problem(), "vertex index 3 (counting from 0) is out of range"));
  }
}

TEST(OffReader, CoordinatesKeepFullDoublePrecision) {
  // OpenMesh's reader passed them through single precision.
  const scene::detail::MeshSoup soup =
      read("tenth.off", "OFF\n3 1 0\n0.1 0 0\n1 0 0\n0 1 1e-300\n3 0 1 2\n");
  ASSERT_EQ(soup.vertices.size(), 3u);
  EXPECT_EQ(soup.vertices[0].x, 0.1);
  EXPECT_EQ(soup.vertices[2].z, 1e-300);
}

TEST(OffReader, VariantsOfTheFormat) {
  // Comments, colours after the indices, the prefixes, the header run together with the
  // counts, no header at all, CRLF lines.
  const scene::detail::MeshSoup plain =
      read("plain.off",
           "# a triangle\r\nOFF\r\n\r\n3 1 0 # counts\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n"
           "3 0 1 2 255 0 0\r\n");
  ASSERT_EQ(plain.faces.size(), 1u);
  EXPECT_EQ(plain.faces[0].vertices, indices({0, 1, 2}));
  EXPECT_EQ(plain.faces[0].line, 8u);
  const scene::detail::MeshSoup coff =
      read("c.off", "COFF\n3 1 0\n0 0 0 1 1 1 1\n1 0 0 0 0 0 1\n0 1 0 9\n3 0 1 2\n");
  ASSERT_EQ(coff.vertices.size(), 3u);
  EXPECT_EQ(coff.vertices[1], glm::dvec3(1, 0, 0));
  const scene::detail::MeshSoup stcnoff =
      read("stcn.off",
           "STCNOFF\n3 1\n0 0 0 0 0 1 1 1 1 0.5 0.5\n1 0 0 0 0 1 1 1 1 0.5 0.5\n"
           "0 1 0 0 0 1 1 1 1 0.5 0.5\n3 0 1 2\n");
  ASSERT_EQ(stcnoff.vertices.size(), 3u);
  EXPECT_EQ(stcnoff.vertices[2], glm::dvec3(0, 1, 0));
  const scene::detail::MeshSoup homogeneous =
      read("h.off", "4OFF\n3 1 0\n0 0 0 2\n2 0 0 2\n0 3 0 0.5\n3 0 1 2\n");
  ASSERT_EQ(homogeneous.vertices.size(), 3u);
  EXPECT_EQ(homogeneous.vertices[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(homogeneous.vertices[2], glm::dvec3(0, 6, 0));
  EXPECT_TRUE(
      Contains(read_error("w0.off", "4OFF\n3 1 0\n0 0 0 0\n2 0 0 2\n0 3 0 1\n3 0 1 2\n").problem(),
               "at infinity"));
  const scene::detail::MeshSoup run_together =
      read("modelnet.off", "OFF3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 2 1 0\n");
  ASSERT_EQ(run_together.faces.size(), 1u);
  EXPECT_EQ(run_together.faces[0].vertices, indices({2, 1, 0}));
  const scene::detail::MeshSoup n_off =
      read("n.off", "nOFF\n3\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(n_off.faces.size(), 1u);
  const scene::detail::MeshSoup headerless =
      read("bare.off", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(headerless.faces.size(), 1u);
  // Records of fewer than 3 indices are kept, for the scene reader to reject with the id.
  const scene::detail::MeshSoup two =
      read("two.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2 0 1\n");
  ASSERT_EQ(two.faces.size(), 2u);
  EXPECT_EQ(two.faces[1].vertices, indices({0, 1}));
}

// Binary OFF: a triangle and a quad, in the given byte order.
std::string binary_off(bool big, std::int32_t faces_announced = 2, bool trailing = false) {
  Bytes b;
  b.raw("OFF BINARY\n").u(4, 4, big).u(static_cast<std::uint32_t>(faces_announced), 4, big);
  b.u(0, 4, big);
  for (const float x : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.1f}) {
    b.f32(x, big);
  }
  b.u(3, 4, big).u(0, 4, big).u(1, 4, big).u(2, 4, big).u(0, 4, big);
  b.u(4, 4, big).u(0, 4, big).u(1, 4, big).u(2, 4, big).u(3, 4, big);
  b.u(3, 4, big).f32(1, big).f32(0, big).f32(0, big);  // a colour
  if (trailing) b.raw("x");
  return b.data;
}

TEST(OffReader, BinaryInEitherByteOrder) {
  for (const bool big : {true, false}) {
    const scene::detail::MeshSoup soup = read("binary.off", binary_off(big));
    ASSERT_EQ(soup.faces.size(), 2u) << big;
    ASSERT_EQ(soup.vertices.size(), 4u);
    EXPECT_EQ(soup.faces[1].vertices, indices({0, 1, 2, 3}));
    EXPECT_EQ(soup.vertices[3], glm::dvec3(0, 1, static_cast<double>(0.1f)));
    EXPECT_TRUE(Contains(read_error("binary_short.off", binary_off(big, 3)).problem(),
                         std::string("binary OFF (") + (big ? "big" : "little") +
                             "-endian): the file ends after 2 of the 3 faces"));
    EXPECT_TRUE(Contains(read_error("binary_long.off", binary_off(big, 2, true)).problem(),
                         "1 bytes after the last face"));
  }
}

TEST(OffReader, JunkAndUtf16AreNotMeshes) {
  EXPECT_TRUE(Contains(read_error("junk.off", std::string("OFF\n3 1 0\n\0\0\0\x01", 14)).problem(),
                       "not a text file (UTF-16?)"));
  std::string utf16;
  for (const char c : std::string("OFF\n3 1 0\n")) utf16 += std::string{c, '\0'};
  EXPECT_TRUE(Contains(read_error("utf16.off", utf16).problem(), "not a text file (UTF-16?)"));
}

// ---- PLY -------------------------------------------------------------------------------

std::string ply_header(const std::string& format, const std::string& coordinate_type,
                       std::int64_t vertices, std::int64_t faces,
                       const std::string& extra_vertex_properties = "") {
  return "ply\nformat " + format + " 1.0\ncomment made by hand\nelement vertex " +
         std::to_string(vertices) + "\nproperty " + coordinate_type + " x\nproperty " +
         coordinate_type + " y\nproperty " + coordinate_type + " z\n" + extra_vertex_properties +
         "element face " + std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(PlyReader, AnAsciiBodyShorterThanTheHeaderSaysIsAnError) {
  // OpenMesh's reader made up the missing face.
  const std::string body = "0 0 0\n1 0 0\n1 1 0.1\n0 1 0\n3 0 1 2\n";
  const InputError e = read_error("short.ply", ply_header("ascii", "double", 4, 2) + body);
  EXPECT_TRUE(Contains(e.problem(),
                       "the file ends after 1 of the 2 'face' elements the header "
                       "announces (truncated?)"));
  ExpectNamesFile(e, "short.ply");
  EXPECT_TRUE(Contains(
      read_error("long.ply", ply_header("ascii", "double", 4, 1) + body + "3 0 2 3\n").problem(),
      "line 16: more data after the elements the header announces"));
  EXPECT_TRUE(Contains(
      read_error("few.ply", ply_header("ascii", "float", 3, 1) + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n")
          .problem(),
      "line 12: the 'vertex' element has fewer values"));
  EXPECT_TRUE(Contains(read_error("many.ply", ply_header("ascii", "float", 3, 1) +
                                                  "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 7\n")
                           .problem(),
                       "1 more values than its properties take"));
  EXPECT_TRUE(Contains(
      read_error("inf.ply", ply_header("ascii", "float", 3, 1) + "0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n")
          .problem(),
      "coordinate z is not finite"));
  EXPECT_TRUE(Contains(read_error("range.ply", ply_header("ascii", "float", 3, 1) +
                                                   "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n")
                           .problem(),
                       "'300' (property 'vertex_indices') is not an integer of its type"));
}

TEST(PlyReader, AsciiCoordinatesKeepFullDoublePrecision) {
  const scene::detail::MeshSoup soup =
      read("tenth.ply", ply_header("ascii", "float", 3, 1) + "0.1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  ASSERT_EQ(soup.faces.size(), 1u);
  EXPECT_EQ(soup.vertices[0].x, 0.1);
  EXPECT_EQ(soup.faces[0].line, 14u);
}

// A binary PLY file: 4 vertices (x y z as double or float, then a uchar colour), a
// triangle and a quad (`faces` of them), an edge element, then `tail`.
std::string binary_ply(bool big, bool doubles, std::int64_t faces, const std::string& tail = "") {
  Bytes b;
  std::string header = ply_header(big ? "binary_big_endian" : "binary_little_endian",
                                  doubles ? "double" : "float", 4, faces, "property uchar red\n");
  header.replace(header.find("end_header"), 10,
                 "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header");
  b.raw(header);
  const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.1}};
  for (const auto& p : xyz) {
    for (const double x : p) {
      if (doubles) {
        b.f64(x, big);
      } else {
        b.f32(static_cast<float>(x), big);
      }
    }
    b.u(200, 1);
  }
  if (faces >= 1) b.u(3, 1).u(0, 4, big).u(1, 4, big).u(2, 4, big);
  if (faces >= 2) b.u(4, 1).u(0, 4, big).u(1, 4, big).u(2, 4, big).u(3, 4, big);
  b.u(0, 4, big).u(1, 4, big);  // the edge
  b.raw(tail);
  return b.data;
}

TEST(PlyReader, BinaryInEitherByteOrderInFullPrecision) {
  for (const bool big : {true, false}) {
    const scene::detail::MeshSoup soup = read("binary.ply", binary_ply(big, true, 2));
    ASSERT_EQ(soup.faces.size(), 2u) << big;
    ASSERT_EQ(soup.vertices.size(), 4u);
    EXPECT_EQ(soup.faces[1].vertices, indices({0, 1, 2, 3}));
    EXPECT_EQ(soup.vertices[3].z, 0.1);  // OpenMesh's reader gave float(0.1)
    const scene::detail::MeshSoup floats = read("floats.ply", binary_ply(big, false, 2));
    ASSERT_EQ(floats.vertices.size(), 4u);
    EXPECT_EQ(floats.vertices[3].z, static_cast<double>(0.1f));
  }
}

TEST(PlyReader, BinaryBodyOfTheWrongLengthIsAnError) {
  // Three faces announced, two written: the edge's 8 bytes are read as the start of a third.
  std::string three = binary_ply(false, true, 2);
  three.replace(three.find("element face 2"), 14, "element face 3");
  EXPECT_TRUE(Contains(read_error("short_binary.ply", three).problem(), "the file ends"));
  std::string truncated = binary_ply(false, true, 2);
  truncated.resize(truncated.size() - 5);
  EXPECT_TRUE(Contains(read_error("cut.ply", truncated).problem(),
                       "the file ends before the 1 'edge' elements"));
  EXPECT_TRUE(Contains(read_error("tail.ply", binary_ply(false, true, 2, "xyz")).problem(),
                       "3 bytes after the last element the header announces"));
}

TEST(PlyReader, MalformedHeadersAreErrors) {
  const std::string good = ply_header("ascii", "float", 3, 1);
  auto with = [&good](const std::string& from, const std::string& to) {
    std::string h = good;
    h.replace(h.find(from), from.size(), to);
    return h + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  };
  for (const auto& [bytes, problem] : std::vector<std::pair<std::string, std::string>>{
           {"plyx\n", "not a PLY file"},
           {"ply\nformat ascii 1.0\nelement vertex 3\n", "no 'end_header'"},
           {with("format ascii 1.0\n", ""), "no 'format' line"},
           {with("ascii", "binary"), "unknown format 'binary'"},
           {with("property float z\n", ""), "the vertex element has no x, y and z"},
           {with("vertex_indices", "indices"), "the face element has no 'vertex_indices'"},
           {with("list uchar int", "list float int"), "a list's count must have an integer"},
           {with("element vertex 3", "element vertex -3"), "count >= 0"},
           {with("comment made by hand", "made by hand"), "unknown header line"},
           {with("element face 1", "element tristrips 1"), "'tristrips' elements are not read"},
       }) {
    EXPECT_TRUE(Contains(read_error("bad.ply", bytes).problem(), problem)) << bytes;
  }
  // vertex_index is the other name in use.
  EXPECT_EQ(read("vertex_index.ply", with("vertex_indices", "vertex_index")).faces.size(), 1u);
}

// ---- Pinched and bridged loops ---------------------------------------------------------

scene::detail::LoopCheck check(const std::vector<clipper::Loop2>& loops) {
  std::vector<std::string> names{"the face"};
  for (std::size_t h = 1; h < loops.size(); ++h) names.push_back("hole " + std::to_string(h - 1));
  return scene::detail::check_loops(loops, names);
}

std::string problem_of(const std::vector<clipper::Loop2>& loops) {
  return check(loops).problem.value_or("");
}

clipper::Loop2 reversed(clipper::Loop2 loop) {
  std::reverse(loop.begin(), loop.end());
  return loop;
}

// A bow: two triangles, both counter-clockwise, touching at the origin, which the loop
// passes twice. Area 2 + 2.
const clipper::Loop2 kBow{{0, 0}, {2, -1}, {2, 1}, {0, 0}, {-2, 1}, {-2, -1}};

TEST(PinchedLoops, ALoopTouchingItselfAtAVertexWithoutCrossingIsValid) {
  const scene::detail::LoopCheck bow = check({kBow});
  EXPECT_FALSE(bow.problem) << *bow.problem;
  EXPECT_EQ(bow.counter_clockwise, std::vector<bool>{true});
  EXPECT_EQ(check({reversed(kBow)}).counter_clockwise, std::vector<bool>{false});
  // Where it starts does not matter.
  const clipper::Loop2 rotated{{2, 1}, {0, 0}, {-2, 1}, {-2, -1}, {0, 0}, {2, -1}};
  EXPECT_FALSE(check({rotated}).problem);
  // A notch whose tip reaches back to the boundary: the loop passes (5,0) twice and
  // bounds the square less a triangle, a pocket closed at one point.
  const clipper::Loop2 pocket{{0, 0}, {5, 0}, {4, 3}, {6, 3}, {5, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_FALSE(check({pocket}).problem) << problem_of({pocket});
  EXPECT_EQ(check({pocket}).counter_clockwise, std::vector<bool>{true});
  // Passing one point three times, a lobe to the right, one above, one to the left.
  const clipper::Loop2 three{{0, 0},  {2, -1}, {2, 1},  {0, 0},  {1, 2},
                             {-1, 2}, {0, 0},  {-2, 1}, {-2, -1}};
  EXPECT_FALSE(check({three}).problem) << problem_of({three});
}

TEST(PinchedLoops, CrossingOverAtTheRepeatedVertexIsNot) {
  // A figure eight: the second lobe runs clockwise, so the loop crosses over at the origin.
  const clipper::Loop2 eight{{0, 0}, {2, -1}, {2, 1}, {0, 0}, {-2, -1}, {-2, 1}};
  EXPECT_TRUE(Contains(problem_of({eight}),
                       "the face intersects itself: it crosses over at "
                       "vertex 0, which it passes again as vertex 3"));
  // A lobe inside the other, touching it at one point and running the same way round:
  // its area would count twice. Its directions at the point interleave.
  const clipper::Loop2 nested{{5, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0},
                              {5, 0}, {6, 1},  {5, 2},   {4, 1}};
  EXPECT_TRUE(Contains(problem_of({nested}), "intersects itself"));
  // The three lobes taken in another order (right, left, above): every direction at the
  // origin still turns the winding number the right way, but the passages cross there.
  const clipper::Loop2 crossed{{0, 0},   {2, -1}, {2, 1}, {0, 0}, {-2, 1},
                               {-2, -1}, {0, 0},  {1, 2}, {-1, 2}};
  EXPECT_TRUE(Contains(problem_of({crossed}), "intersects itself"));
  // Touching itself inside an edge is no repeated vertex: still an error.
  const clipper::Loop2 t_touch{{0, 0}, {4, 0}, {4, 3}, {2, 0}, {0, 3}};
  EXPECT_TRUE(Contains(problem_of({t_touch}), "the face intersects itself (edges"));
  // Nor is doubling back along an edge (found as that, or as the vertex it stops at
  // touching the edge it came by).
  const std::string spike = problem_of({{{0, 0}, {4, 0}, {4, 4}, {4, 2}, {0, 4}}});
  EXPECT_TRUE(Contains(spike, "doubles back") || Contains(spike, "intersects itself")) << spike;
  EXPECT_TRUE(Contains(problem_of({{{0, 0}, {4, 0}, {4, 4}, {4, 0}, {0, 4}}}), "doubles back"));
}

// A square annulus cut open by a bridge from its outer corner (-2,-2) to its inner corner
// (-1,-1), run once each way (a keyhole, as exporters write a face with a hole): the
// outer square counter-clockwise, the inner clockwise. Area 16 - 4.
const clipper::Loop2 kKeyhole{{-2, -2}, {2, -2}, {2, 2}, {-2, 2}, {-2, -2},
                              {-1, -1}, {-1, 1}, {1, 1}, {1, -1}, {-1, -1}};

TEST(PinchedLoops, ABridgeRunOnceEachWayIsValid) {
  const scene::detail::LoopCheck keyhole = check({kKeyhole});
  EXPECT_FALSE(keyhole.problem) << *keyhole.problem;
  EXPECT_EQ(keyhole.counter_clockwise, std::vector<bool>{true});
  EXPECT_EQ(check({reversed(kKeyhole)}).counter_clockwise, std::vector<bool>{false});
  // A chain of two bridge edges, and a bridge between two lobes side by side (a
  // dumbbell), whose bridge runs outside the region.
  const clipper::Loop2 chain{{-4, -4}, {4, -4}, {4, 4}, {-4, 4}, {-4, -4}, {-3, -2},
                             {-1, -1}, {-1, 1}, {1, 1}, {1, -1}, {-1, -1}, {-3, -2}};
  EXPECT_FALSE(check({chain}).problem) << problem_of({chain});
  EXPECT_EQ(check({chain}).counter_clockwise, std::vector<bool>{true});
  const clipper::Loop2 barbell{{0, 0}, {2, 0}, {3, 0}, {5, 0}, {5, 2},
                               {3, 2}, {3, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_FALSE(check({barbell}).problem) << problem_of({barbell});
  // A bridge that is not a whole edge both ways: an error still.
  const clipper::Loop2 partial{{-2, -2}, {2, -2}, {2, 2},  {-2, 2},  {-2, -2},    {-1, -1},
                               {-1, 1},  {1, 1},  {1, -1}, {-1, -1}, {-1.5, -1.5}};
  EXPECT_TRUE(Contains(problem_of({partial}), "intersects itself"));
}

TEST(PinchedLoops, ABridgeToABoundaryRunningTheWrongWayIsNot) {
  // The inner square counter-clockwise too: it would count its area twice.
  const clipper::Loop2 twice{{-2, -2}, {2, -2}, {2, 2}, {-2, 2}, {-2, -2},
                             {-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
  EXPECT_TRUE(Contains(problem_of({twice}), "the face overlaps itself"));
  // Two lobes side by side joined by a bridge, one running the other way round.
  const clipper::Loop2 opposite{{0, 0}, {2, 0}, {3, 0}, {3, 2}, {5, 2},
                                {5, 0}, {3, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_TRUE(Contains(problem_of({opposite}), "overlaps itself"));
  // A hole whose vertex lies on the bridge, on both sides of it.
  EXPECT_TRUE(Contains(problem_of({kKeyhole, {{-1.5, -1.5}, {-1.2, -1.8}, {-1.8, -1.2}}}),
                       "hole 0 crosses the face"));
}

TEST(PinchedLoops, BridgesThatBranchAreNot) {
  // A quadrilateral with three bridges from (0,2) to three of its corners: the winding
  // number is right everywhere, but the bridges' two sides cannot be pulled apart without
  // crossing.
  const clipper::Loop2 star{{4, 0}, {0, 2}, {3, 1}, {3, 3}, {0, 2},
                            {4, 0}, {3, 1}, {0, 2}, {3, 3}, {4, 4}};
  EXPECT_TRUE(Contains(problem_of({star}), "runs both ways along edges that branch at vertex"));
  // A path of two bridges from (2,1) round by (0,1) to (3,4), both corners of one triangle
  // of a pair: fine.
  const clipper::Loop2 path{{2, 1}, {3, 4}, {0, 1}, {2, 1}, {4, 2},
                            {4, 0}, {2, 1}, {0, 1}, {3, 4}, {3, 2}};
  EXPECT_FALSE(check({path}).problem) << problem_of({path});
  EXPECT_EQ(check({path}).counter_clockwise, std::vector<bool>{false});
}

TEST(PinchedLoops, HolesAtAPinch) {
  // A hole in the right lobe of a bow, touching the pinch point: inside.
  const clipper::Loop2 in_lobe{{0, 0}, {1.5, -0.25}, {1.5, 0.25}};
  EXPECT_FALSE(check({kBow, in_lobe}).problem) << problem_of({kBow, in_lobe});
  // A triangle in the notch above the pinch point, between the lobes: outside.
  const clipper::Loop2 in_notch{{0, 0}, {0.5, 2}, {-0.5, 2}};
  EXPECT_TRUE(Contains(problem_of({kBow, in_notch}), "hole 0 is not inside the face"));
  // A hole straddling a lobe's edge at the pinch point crosses it.
  const clipper::Loop2 straddling{{0, 0}, {1, -1}, {1, 0}};
  EXPECT_TRUE(check({kBow, straddling}).problem);
  // A hole touching the keyhole's bridge end inside the annulus, beside the bridge.
  const clipper::Loop2 by_bridge{{-1, -1}, {-1.2, -1.8}, {-1.1, -1.9}};
  EXPECT_FALSE(check({kKeyhole, by_bridge}).problem) << problem_of({kKeyhole, by_bridge});
  // A hole straddling the bridge where it ends.
  const clipper::Loop2 across_bridge{{-1, -1}, {-1.2, -1.8}, {-1.8, -1.2}};
  EXPECT_TRUE(check({kKeyhole, across_bridge}).problem);
}

// ---- Pinched faces in scenes, downstream -----------------------------------------------

// The bow in the plane z = `z`, its far left vertex raised by `lift`.
std::string bow_obj(double z = 0, double lift = 0) {
  auto v = [](double x, double y, double zz) {
    return "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(zz) + "\n";
  };
  return v(0, 0, z) + v(2, -1, z) + v(2, 1, z) + v(-2, 1, z + lift) + v(-2, -1, z) +
         "f 1 2 3 1 4 5\n";
}

TEST(PinchedFaces, APinchedMeshFaceIsTheRegionItBounds) {
  const ReadResult r = read_scene_with_mesh("bow.obj", bow_obj());
  ASSERT_EQ(r.scene.faces.size(), 1u);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(hsr::area(r.scene.faces[0].parts), 4.0);
  EXPECT_EQ(r.scene.faces[0].parts[0].outer.size(), 6u);  // kept as given
}

// A vertical annulus, as a keyhole face in the plane x = -1.146, like the
// concave_polygon.obj model in assimp's tests: an outer n-gon and an inner one joined by
// a bridge at the top.
std::string keyhole_obj(int n) {
  std::string obj;
  auto v = [&obj](double y, double z) {
    char line[80];
    std::snprintf(line, sizeof line, "v -1.146 %.17g %.17g\n", y, z);
    obj += line;
  };
  for (int i = 0; i < n; ++i) {
    const double a = std::numbers::pi / 2 + 2 * std::numbers::pi * i / n;
    v(2.4 + 0.7 * std::cos(a), 2.35 + 0.7 * std::sin(a));
  }
  for (int i = 0; i < n; ++i) {
    const double a = std::numbers::pi / 2 + 2 * std::numbers::pi * i / n;
    v(2.4 + 0.6 * std::cos(a), 2.35 + 0.6 * std::sin(a));
  }
  // Outer counter-clockwise from the top, back to the top, the bridge down to the inner
  // top, the inner ring clockwise, back up the bridge.
  obj += "vn 1 0 0\nf";
  auto corner = [&obj](int vertex) {
    obj.append(" ").append(std::to_string(vertex)).append("//1");
  };
  for (int i = 0; i <= n; ++i) corner(i % n + 1);
  for (int i = 0; i <= n; ++i) corner(n + (n - i) % n + 1);
  return obj + "\n";
}

TEST(PinchedFaces, AKeyholeMeshFaceIsTheAnnulus) {
  const int n = 32;
  const ReadResult r = read_scene_with_mesh("keyhole.obj", keyhole_obj(n));
  ASSERT_EQ(r.scene.faces.size(), 1u);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings[0];
  const double ring = 0.5 * n * std::sin(2 * std::numbers::pi / n);
  EXPECT_NEAR(hsr::area(r.scene.faces[0].parts), ring * (0.49 - 0.36), 1e-12);
}

// The xy-projected area of a face's parts, each part's triangle counted with its sign.
double projected_area(const Face& face) {
  double sum = 0;
  for (const hsr::Polygon3& part : face.parts) {
    clipper::Loop2 loop;
    for (const glm::dvec3& p : part.outer) loop.push_back({p.x, p.y});
    sum += clipper::signed_area(loop);
  }
  return sum;
}

TEST(PinchedFaces, NonPlanarPinchedFacesAreSplitIntoTheirTriangles) {
  // The bow with a vertex lifted: two triangles, one per lobe.
  const ReadResult r = read_scene_with_mesh("bent_bow.obj", bow_obj(0, 1));
  ASSERT_EQ(r.scene.faces[0].parts.size(), 2u);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(Contains(r.warnings[0], "not planar"));
  EXPECT_NEAR(hsr::area(r.scene.faces[0].parts), 2 + std::sqrt(21.0) / 2, 1e-12);
  EXPECT_EQ(projected_area(r.scene.faces[0]), 4.0);
  // Lobes of two triangles each: right, above, left.
  const ReadResult lobes = read_scene_with_mesh(
      "bent_lobes.obj",
      "v 0 0 0\nv 2 -1 0\nv 3 0 0.5\nv 2 1 0\nv -2 1 0\nv -3 0 0.25\nv -2 -1 0\n"
      "v 0 3 0\nv 1 2 0\nv -1 2 0\n"
      "f 1 2 3 4 1 9 8 10 1 5 6 7\n");
  ASSERT_EQ(lobes.warnings.size(), 1u);
  EXPECT_EQ(lobes.scene.faces[0].parts.size(), 6u);
  EXPECT_EQ(projected_area(lobes.scene.faces[0]), 3.0 + 3.0 + 3.0);
  for (const hsr::Polygon3& part : lobes.scene.faces[0].parts) {
    clipper::Loop2 loop;
    for (const glm::dvec3& p : part.outer) loop.push_back({p.x, p.y});
    EXPECT_GT(clipper::signed_area(loop), 0.0);
  }
}

TEST(PinchedFaces, NonPlanarKeyholeFacesAreSplitIntoTheirTriangles) {
  // The square keyhole with its bridge at each corner in turn (so at the lowest vertex of
  // the projection too), each outer corner lifted in turn.
  const double outer[4][2] = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  const double inner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int bridge = 0; bridge < 4; ++bridge) {
    for (int lifted = 0; lifted < 4; ++lifted) {
      std::ostringstream obj;
      for (int k = 0; k < 4; ++k) {
        obj << "v " << outer[k][0] << " " << outer[k][1] << (k == lifted ? " 0.5\n" : " 0\n");
      }
      for (int k = 0; k < 4; ++k) obj << "v " << inner[k][0] << " " << inner[k][1] << " 0\n";
      obj << "f";
      for (int k = 0; k <= 4; ++k) obj << " " << (bridge + k) % 4 + 1;
      for (int k = 0; k <= 4; ++k) obj << " " << (bridge - k + 8) % 4 + 5;
      obj << "\n";
      const ReadResult r = read_scene_with_mesh("bent_keyhole.obj", obj.str());
      ASSERT_EQ(r.warnings.size(), 1u);
      EXPECT_TRUE(Contains(r.warnings[0], "not planar"));
      EXPECT_EQ(projected_area(r.scene.faces[0]), 12.0) << bridge << " " << lifted;
      for (const hsr::Polygon3& part : r.scene.faces[0].parts) {
        clipper::Loop2 loop;
        for (const glm::dvec3& p : part.outer) loop.push_back({p.x, p.y});
        EXPECT_GT(clipper::signed_area(loop), 0.0);
      }
    }
  }
}

// A 10 x 10 ground at z = 0 under a mesh face at z = 1, the sun straight down.
ShadowedScene shadowed(const std::string& obj_name, const std::string& obj) {
  const ReadResult r = read_scene_with_mesh(
      obj_name, obj,
      R"(, "polygons": [{"id": "ground", "outer": [[-5,-5,0],[5,-5,0],[5,5,0],[-5,5,0]]}],
          "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}])");
  GenerateOptions options;
  options.threads = 1;
  return generate_shadows(r.scene, options).shadowed;
}

TEST(PinchedFaces, APinchedFaceCastsTheShadowOfItsRegion) {
  const ShadowedScene s = shadowed("bow_above.obj", bow_obj(1));
  ASSERT_EQ(s.scene().faces.size(), 2u);
  EXPECT_NEAR(lit_area(s.lit()[0][0]), 100.0 - 4.0, 1e-9);  // the ground
  EXPECT_NEAR(lit_area(s.lit()[1][0]), 4.0, 1e-9);          // the bow itself
}

TEST(PinchedFaces, AKeyholeFaceCastsTheShadowOfTheAnnulus) {
  const ShadowedScene s =
      shadowed("keyhole_above.obj",
               "v -2 -2 1\nv 2 -2 1\nv 2 2 1\nv -2 2 1\nv -1 -1 1\nv -1 1 1\nv 1 1 1\nv 1 -1 1\n"
               "f 1 2 3 4 1 5 6 7 8 5\n");
  EXPECT_NEAR(lit_area(s.lit()[0][0]), 100.0 - 12.0, 1e-9);
  EXPECT_NEAR(lit_area(s.lit()[1][0]), 12.0, 1e-9);
}

}  // namespace
}  // namespace shadowgen
