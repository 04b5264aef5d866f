#pragma once

// Mesh files read as polygon soups: every face record of the file, in file order, with
// the vertex indices it names. Nothing is welded, nothing dropped, nothing checked beyond
// the file's syntax; the scene reader checks the indices and the geometry, and names face
// record k "<mesh id>/<k>". So a soup, a non-manifold mesh or an open model loses no face.
//
// Formats, by file extension (case-insensitive), each read strictly: a file that is not a
// readable mesh of its format (binary junk, UTF-16 text, a truncated file, a header that
// announces more elements than follow, or fewer) is an error, and nothing is made up:
//   .obj  obj_reader.h, coordinates in full double precision;
//   .stl  stl_reader.h, ASCII or binary (told apart by the file size); binary STL stores
//         single-precision floats, which convert to double exactly;
//   .off  off_reader.h, text or binary, coordinates as the file gives them (text in full
//         double precision);
//   .ply  ply_reader.h, ASCII or binary, coordinates as the file gives them (double
//         properties and ASCII text in full double precision);
//   the other formats OpenMesh reads (its own .om): through OpenMesh's readers and an
//         importer that records what they deliver. Those readers hand vertices over as
//         single-precision floats (OpenMesh::Vec3f) and are lenient with malformed files.
// None of the four goes through OpenMesh, whose readers drop faces or invent them: the
// OBJ reader removes repeated vertex indices and skips faces left with fewer than three,
// the STL reader welds vertices and skips triangles with repeated ones, and the OFF and
// ASCII PLY readers, given fewer faces than their header announces, make up the missing
// ones from the last line read. Dropping would lose the degenerate faces the scene format
// keeps and shift the numbering of the faces after them.
//
// A file that yields no face record is an error too: a mesh is referenced for its faces.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadowgen::scene::detail {

struct MeshFaceRecord {
  std::vector<std::int64_t> vertices;  // 0-based; may be out of range (the caller checks)
  std::size_t line = 0;                // 1-based line of a text file; 0 when not known
};

struct MeshSoup {
  std::vector<glm::dvec3> vertices;
  std::vector<MeshFaceRecord> faces;
};

// Throws InputError naming `file` (and the face "<mesh_id>/<k>" when a face record is
// at fault) when the file cannot be read or parsed, or holds no face record.
MeshSoup read_mesh(const std::filesystem::path& file, const std::string& mesh_id);

}  // namespace shadowgen::scene::detail
