#include "detail/gltf_mesh.h"

#include <limits>
#include <stdexcept>

#include "hsr/chart_triangles.h"

namespace shadowgen::detail {

bool GltfMesh::add_piece(const Face& face, std::size_t face_index,
                         std::span<const LitPolygon> polygons, double area,
                         std::optional<double> hours) {
  // Triangulated whole before anything is added, so that a failure leaves the mesh as it
  // was.
  std::vector<std::pair<const LitPolygon*, hsr::ChartTriangles>> splits;
  std::vector<glm::dvec3> part_normals;
  for (const hsr::Polygon3& part : face.parts) {
    part_normals.push_back(hsr::plane_of(part).normal);  // unit
  }
  for (const LitPolygon& lit : polygons) {
    std::optional<hsr::ChartTriangles> split =
        hsr::chart_triangles(lit.polygon, part_normals.at(lit.part));
    if (!split) return false;
    splits.emplace_back(&lit, std::move(*split));
  }

  const std::size_t first_triangle = indices_.size() / 3;
  // A vertex is shared within the piece where its point and part are the same.
  std::map<std::tuple<double, double, double, std::size_t>, std::uint32_t> shared;
  const auto vertex = [&](const glm::dvec3& p, std::size_t part) {
    const auto [it, added] =
        shared.emplace(std::tuple{p.x, p.y, p.z, part}, static_cast<std::uint32_t>(0));
    if (added) {
      if (positions_.size() >= std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("glTF export: more vertices than uint32 indices can number");
      }
      it->second = static_cast<std::uint32_t>(positions_.size());
      positions_.push_back(p);
      normals_.push_back(part_normals[part]);
    }
    return it->second;
  };
  for (const auto& [lit, split] : splits) {
    for (std::size_t k = 0; k < split.triangles.size(); ++k) {
      if (split.flat_triangle(k)) continue;  // no area
      for (const std::size_t corner : split.triangles[k]) {
        indices_.push_back(vertex(split.corners[corner], lit->part));
      }
    }
  }
  pieces_.face.push_back(face_index);
  pieces_.first_triangle.push_back(first_triangle);
  pieces_.area.push_back(area);
  if (hours) pieces_.hours.push_back(*hours);
  return true;
}

}  // namespace shadowgen::detail
