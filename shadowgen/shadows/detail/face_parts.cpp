#include "face_parts.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "coplanar_groups.h"
#include "hsr/area.h"
#include "hsr/parallel.h"

namespace shadowgen::detail {

FaceParts flatten(const Scene& scene) {
  FaceParts parts;
  parts.face_count = scene.faces.size();
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t k = 0; k < scene.faces[f].parts.size(); ++k) {
      const hsr::Polygon3& p = scene.faces[f].parts[k];
      parts.polygons.push_back(p);
      parts.owners.push_back({f, k});
      for (const glm::dvec3& v : p.outer) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
    }
  }
  // The planes and areas in parallel, on the threads of the calling task arena.
  parts.planes.resize(parts.polygons.size());
  parts.areas.resize(parts.polygons.size());
  hsr::for_each_in_parallel(parts.polygons.size(), [&parts](std::size_t i) {
    parts.planes[i] = hsr::plane_of(parts.polygons[i]);
    parts.areas[i] = hsr::area(parts.polygons[i]);
  });
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

}  // namespace shadowgen::detail
