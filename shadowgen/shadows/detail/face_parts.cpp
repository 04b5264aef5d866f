#include "face_parts.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "coplanar_groups.h"
#include "hsr/area.h"
#include "hsr/parallel.h"

namespace shadowgen::shadows::detail {

FaceParts flatten(const Scene& scene) {
  FaceParts parts;
  parts.face_count = scene.faces.size();
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t k = 0; k < scene.faces[f].parts.size(); ++k) parts.owners.push_back({f, k});
  }
  // The copies, planes, areas and boxes in parallel, on the threads of the calling task
  // arena; the box of them all from the parts' boxes in order (min and max are exact).
  const std::size_t n = parts.owners.size();
  parts.polygons.resize(n);
  parts.planes.resize(n);
  parts.areas.resize(n);
  std::vector<glm::dvec3> low(n, glm::dvec3(INFINITY)), high(n, glm::dvec3(-INFINITY));
  hsr::for_each_in_parallel(n, [&](std::size_t i) {
    const PartOwner& owner = parts.owners[i];
    const hsr::Polygon3& p = parts.polygons[i] = scene.faces[owner.face].parts[owner.part];
    for (const glm::dvec3& v : p.outer) {
      low[i] = glm::min(low[i], v);
      high[i] = glm::max(high[i], v);
    }
    parts.planes[i] = hsr::plane_of(p);
    parts.areas[i] = hsr::area(p);
  });
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t i = 0; i < n; ++i) {
    lo = glm::min(lo, low[i]);
    hi = glm::max(hi, high[i]);
  }
  // The box's point nearest the world's origin, not its middle: an image coordinate is
  // then off by a few ulps of min(2|p|, the box's diagonal) for every scene point p. The
  // middle of a box that spans 1e14 would cost a face near the origin 1e-2 in its lit
  // outline, far beyond the rounding its own coordinates allow (what the database reader
  // checks); a compact scene far from the origin keeps the precision of a nearby centre.
  if (!parts.polygons.empty()) parts.centre = glm::clamp(glm::dvec3(0.0), lo, hi);
  parts.coplanar = coplanar_groups(parts.polygons, parts.planes);
  return parts;
}

bool faces_light(const hsr::Plane3& plane, const Light& light) {
  if (glm::length(plane.normal) == 0.0) return false;
  if (light.type == LightType::kDirectional) return glm::dot(plane.normal, light.direction) < 0.0;
  return plane.signed_distance(light.position) > 0.0;
}

}  // namespace shadowgen::shadows::detail
