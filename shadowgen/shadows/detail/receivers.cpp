#include "receivers.h"

#include "shadowgen/shadows/light_views.h"

namespace shadowgen::detail {
namespace {

bool beyond_range(const hsr::Polygon3& polygon, const hsr::Plane3& plane, const Light& light) {
  return light.type == LightType::kPoint && light.range &&
         distance_to_polygon(light.position, polygon, plane) > light.range->end;
}

}  // namespace

Receivers::Receivers(const FaceParts& parts, const Light& light, LightStats& stats)
    : parts_(parts), light_(light) {
  const std::size_t n = parts.size();
  part_.reserve(n);
  lit_side_.reserve(n);
  coplanar_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (beyond_range(parts.polygons[i], parts.planes[i], light)) {
      ++stats.faces_culled_range;
      continue;
    }
    const bool lit = faces_light(parts.planes[i], light);
    if (!lit) ++stats.faces_facing_away;
    part_.push_back(i);
    lit_side_.push_back(lit ? 1 : 0);
    coplanar_.push_back(parts.coplanar[i]);
  }
  stats.faces_considered = part_.size();
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
