#include "detail/gltf_mesh.h"

#include <limits>
#include <stdexcept>

#include "hsr/chart_triangles.h"

namespace shadowgen::output::detail {

bool GltfMesh::add_piece(const Face& face, std::size_t face_index,
                         std::span<const LitPolygon> polygons, double area,
                         std::optional<double> hours) {
  // Triangulated whole before anything is added, so that a failure leaves the mesh as it
  // was.
  std::vector<hsr::ChartTriangles> splits;
  for (const LitPolygon& lit : polygons) {
    std::optional<hsr::ChartTriangles> split =
        hsr::tiled_chart_triangles(lit.polygon, hsr::plane_of(face.parts.at(lit.part)).normal);
    if (!split) return false;
    splits.push_back(std::move(*split));
  }

  const std::size_t first_triangle = indices_.size() / 3;
  if (pieces_.face.empty() || shared_face_ != face_index) shared_.clear();
  shared_face_ = face_index;
  const auto vertex = [&](const glm::dvec3& p) {
    const auto [it, added] = shared_.emplace(std::tuple{p.x, p.y, p.z}, std::uint32_t{0});
    if (added) {
      if (positions_.size() >= std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("glTF export: more vertices than uint32 indices can number");
      }
      it->second = static_cast<std::uint32_t>(positions_.size());
      positions_.push_back(p);
      vertex_faces_.push_back(face_index);
    }
    return it->second;
  };
  for (const hsr::ChartTriangles& split : splits) {
    for (std::size_t k = 0; k < split.triangles.size(); ++k) {
      if (split.flat_triangle(k)) continue;  // no area
      for (const std::size_t corner : split.triangles[k]) {
        indices_.push_back(vertex(split.corners[corner]));
      }
    }
  }
  pieces_.face.push_back(face_index);
  pieces_.first_triangle.push_back(first_triangle);
  pieces_.area.push_back(area);
  if (hours) pieces_.hours.push_back(*hours);
  return true;
}

}  // namespace shadowgen::output::detail
