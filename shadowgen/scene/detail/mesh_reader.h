#pragma once

// Mesh files read as polygon soups: every face record of the file, in file order, with
// the vertex indices it names. Nothing is welded, nothing dropped, nothing checked beyond
// the file's syntax; the scene reader checks the indices and the geometry, and names face
// record k "<mesh id>/<k>". So a soup, a non-manifold mesh or an open model loses no face.
//
// Formats, by file extension (case-insensitive):
//   .obj  read here, coordinates in full double precision;
//   .stl  read here, ASCII or binary (told apart by the file size); binary STL stores
//         single-precision floats, which convert to double exactly;
//   .off, .ply and the other formats OpenMesh reads: through OpenMesh's readers and an
//         importer that records what they deliver. Limitation: those readers hand
//         vertices over as single-precision floats (OpenMesh::Vec3f), so such mesh
//         coordinates keep only about 7 significant digits. Polygons written in the scene's
//         JSON keep full double precision.
// OBJ and STL do not go through OpenMesh because its readers drop faces there: the OBJ
// reader removes repeated vertex indices and skips faces left with fewer than three, the
// STL reader welds vertices and skips triangles with repeated ones. That would lose the
// degenerate faces the scene format keeps and shift the numbering of the faces after them.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadowgen::detail {

struct MeshFaceRecord {
  std::vector<std::int64_t> vertices;  // 0-based; may be out of range (the caller checks)
  std::size_t line = 0;                // 1-based line of a text file; 0 when not known
};

struct MeshSoup {
  std::vector<glm::dvec3> vertices;
  std::vector<MeshFaceRecord> faces;
};

// Throws InputError naming `file` (and the face "<mesh_id>/<k>" when a face record is
// at fault) when the file cannot be read or parsed.
MeshSoup read_mesh(const std::filesystem::path& file, const std::string& mesh_id);

}  // namespace shadowgen::detail
