#pragma once

// One material's mesh of the glTF export (shadowgen/output/gltf_export.h): the triangles
// of its pieces, in scene coordinates and double until the file is written, and the
// pieces' columns that its extras hold.

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <span>
#include <tuple>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::output::detail {

// The pieces by column: piece k is the region(s) of face face[k], its triangles from
// first_triangle[k] on, its area `area[k]`, its sun hours `hours[k]` (sun hours only).
struct GltfPieces {
  std::vector<std::size_t> face;
  std::vector<std::size_t> first_triangle;
  std::vector<double> area;
  std::vector<double> hours;
};

class GltfMesh {
 public:
  // Adds `polygons`, on the parts of `face` (face `face_index` of the scene), as one piece
  // of area `area`: each triangulated in the plane chart of its part by ear clipping
  // (hsr/chart_triangles.h) on its own vertices, counter-clockwise seen from the front,
  // triangles without area left out. A vertex is shared by the triangles of one face's
  // pieces added one after the other (several regions of a face in one band), not with
  // another face's. `hours` for a sun-hours piece. False when a polygon could not be
  // split into triangles (valid regions always are); the mesh is then left as it was.
  bool add_piece(const Face& face, std::size_t face_index, std::span<const LitPolygon> polygons,
                 double area, std::optional<double> hours = std::nullopt);

  bool empty() const { return indices_.empty(); }
  const std::vector<glm::dvec3>& positions() const { return positions_; }
  const std::vector<std::uint32_t>& indices() const { return indices_; }          // 3 per triangle
  const std::vector<std::size_t>& vertex_faces() const { return vertex_faces_; }  // per vertex
  const GltfPieces& pieces() const { return pieces_; }

 private:
  std::vector<glm::dvec3> positions_;
  std::vector<std::size_t> vertex_faces_;  // the face index of each vertex
  std::vector<std::uint32_t> indices_;
  GltfPieces pieces_;
  // The vertices of the face added last, by point, and that face.
  std::map<std::tuple<double, double, double>, std::uint32_t> shared_;
  std::size_t shared_face_ = 0;
};

}  // namespace shadowgen::output::detail
