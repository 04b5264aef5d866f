#include "stencil_parts.h"

#include "ridge_edge_loops.h"

namespace shadowgen::view::detail {
namespace {

using glm::dvec3;

bool casts_volume(const StencilPart& part) {
  return occludes(part.role) && part.light_side != 0 && !part.triangles.triangles.empty();
}

}  // namespace

std::vector<StencilPart> stencil_parts(const Scene& scene, const Light& light) {
  const ScenePartPlanes all(scene);
  const std::vector<PartRole> roles = part_roles(all.polygons, all.planes, light);
  const std::vector<hsr::Plane3>& planes = all.planes;
  std::vector<StencilPart> parts;
  std::size_t k = 0;
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      StencilPart info;
      info.polygon = &part;
      info.plane = planes[k];
      info.role = roles[k];
      info.triangles = sampled::part_triangles(part);
      const dvec3& n = info.plane.normal;
      const double side = light.type == LightType::kDirectional
                              ? -glm::dot(n, light.direction)
                              : info.plane.signed_distance(light.position);
      info.light_side = n == dvec3(0.0) ? 0 : side > 0.0 ? 1 : side < 0.0 ? -1 : 0;
      parts.push_back(std::move(info));
      ++k;
    }
  }
  return parts;
}

SilhouetteMarks silhouette_marks(const Scene& scene, const Light& light) {
  const ScenePartPlanes all(scene);
  const std::vector<PartRole> roles = part_roles(all.polygons, all.planes, light);
  const RidgeEdgeLoops ridges = ridge_edge_loops(all.polygons, all.planes, roles, light);
  SilhouetteMarks marks(all.polygons.size());
  for (std::size_t p = 0; p < marks.size(); ++p) {
    for (const std::vector<std::size_t>& loop : ridges.part_loop_edges[p]) {
      std::vector<bool>& loop_marks = marks[p].emplace_back();
      for (const std::size_t edge : loop) {
        loop_marks.push_back(ridges.edges[edge].kind == EdgeKind::kRidge);
      }
    }
  }
  return marks;
}

bool builds_volume(const StencilPart& part, const SilhouetteMarks* marks) {
  return casts_volume(part) && (marks == nullptr || part.light_side > 0);
}

}  // namespace shadowgen::view::detail
