#include "receivers.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "shadowgen/shadows/light_views.h"

namespace shadowgen::detail {

Receivers::Receivers(const FaceParts& parts, const Light& light, LightStats& stats)
    : parts_(parts), light_(light) {
  const std::size_t n = parts.size();
  // A point light with a range receives on the parts that reach inside range.end. Those
  // still take the shadows of everything between them and the light (the spec's meaning
  // of lit), and a segment from the light to a receiver's point is no longer than the
  // receiver's farthest vertex: a part nearer than that farthest distance over all
  // receivers may occlude, one beyond it cannot.
  const bool ranged = light.type == LightType::kPoint && light.range.has_value();
  std::vector<double> distance(ranged ? n : 0);
  double reach = 0.0;  // the farthest receiver vertex from the light
  for (std::size_t i = 0; ranged && i < n; ++i) {
    distance[i] = distance_to_polygon(light.position, parts.polygons[i], parts.planes[i]);
    if (distance[i] > light.range->end) continue;
    for (const glm::dvec3& v : parts.polygons[i].outer) {
      reach = std::max(reach, glm::length(v - light.position));
    }
  }
  part_.reserve(n);
  lit_side_.reserve(n);
  coplanar_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    bool receives = true;
    if (ranged && distance[i] > light.range->end) {
      ++stats.faces_culled_range;
      if (!(distance[i] <= reach)) continue;
      receives = false;  // beyond the range, but between the light and some receiver
    }
    const bool lit = receives && faces_light(parts.planes[i], light);
    if (receives && !lit) ++stats.faces_facing_away;
    if (receives) ++stats.faces_considered;
    part_.push_back(i);
    lit_side_.push_back(lit ? 1 : 0);
    coplanar_.push_back(parts.coplanar[i]);
  }
  if (part_.size() < n) {
    polygons_in_range_.reserve(part_.size());
    planes_in_range_.reserve(part_.size());
    for (std::size_t i : part_) {
      polygons_in_range_.push_back(parts.polygons[i]);
      planes_in_range_.push_back(parts.planes[i]);
    }
  }
}

std::span<const hsr::Polygon3> Receivers::polygons() const {
  if (part_.size() < parts_.size()) return polygons_in_range_;
  return parts_.polygons;
}

std::span<const hsr::Plane3> Receivers::planes() const {
  if (part_.size() < parts_.size()) return planes_in_range_;
  return parts_.planes;
}

}  // namespace shadowgen::detail
