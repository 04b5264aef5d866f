#pragma once

// The scene's parts as a light sees them, for stencil shadow volumes (shadowgen/view/
// stencil_shadows.h): each part's plane, triangles, role and side toward the light, which
// parts build a volume, and its side edges, every edge of its loops or the silhouette
// edges alone.

#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/sampled/part_triangles.h"
#include "shadowgen/shadows/light_scope.h"

namespace shadowgen::view::detail {

// One part of a face under the light.
struct StencilPart {
  const hsr::Polygon3* polygon = nullptr;
  hsr::Plane3 plane;
  sampled::PartTriangles triangles;
  PartRole role = PartRole::kFacing;
  int light_side = 0;  // +1: the light on the front side, −1 on the back, 0 in the plane
};

// Every part of the scene's faces, in order, with its role under `light` (shadows/
// light_scope.h) and the side of its plane the light is on.
std::vector<StencilPart> stencil_parts(const Scene& scene, const Light& light);

// Per part, per loop (outer first, then holes), per edge from vertex i to i + 1: whether it
// is a silhouette edge, shared by exactly two parts of which one has the light on its front
// side (ridge_edge_loops.h, EdgeKind::kRidge). Empty for the parts the light leaves out.
using SilhouetteMarks = std::vector<std::vector<std::vector<bool>>>;

SilhouetteMarks silhouette_marks(const Scene& scene, const Light& light);

// Whether the part builds a volume: every part that casts one, or with silhouette marks
// only the front parts (their caps; the silhouette edges are theirs).
bool builds_volume(const StencilPart& part, const SilhouetteMarks* marks);

// Calls visit(a, b) for each side edge of the part's volume, directed counter-clockwise
// about its normal toward the light: every edge of its loops, or with `marks` (the part's
// own, per loop) the silhouette edges only.
template <typename Visit>
void for_each_side_edge(const StencilPart& part, const std::vector<std::vector<bool>>* marks,
                        Visit&& visit) {
  const glm::dvec3 m = part.plane.normal * static_cast<double>(part.light_side);
  auto loop_edges = [&](const hsr::Loop3& loop, bool outer, std::size_t index) {
    const double turn = glm::dot(hsr::newell_vector(loop), m);
    const bool forward = outer ? turn > 0.0 : turn < 0.0;
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (marks != nullptr && !(*marks)[index][i]) continue;
      glm::dvec3 a = loop[i], b = loop[(i + 1) % n];
      if (!forward) std::swap(a, b);
      if (a == b) continue;
      visit(a, b);
    }
  };
  loop_edges(part.polygon->outer, true, 0);
  for (std::size_t h = 0; h < part.polygon->holes.size(); ++h) {
    loop_edges(part.polygon->holes[h], false, h + 1);
  }
}

}  // namespace shadowgen::view::detail
