#include "receivers.h"

#include "shadowgen/shadows/light_scope.h"

namespace shadowgen::shadows::detail {

Receivers::Receivers(const FaceParts& parts, const Light& light, LightStats& stats,
                     const ClosedSolids* solids)
    : parts_(parts), light_(light) {
  const std::size_t n = parts.size();
  // The light's scope (light_scope.h): a point light with a range receives on the parts
  // that reach inside range.end; those still take the shadows of every part near enough to
  // stand between them and the light, kept as occluders that receive nothing.
  const std::vector<PartRole> roles = part_roles(parts.polygons, parts.planes, light);
  const std::vector<char> behind_solid =
      solids != nullptr ? solids->need_not_occlude(light) : std::vector<char>(n, 0);
  part_.reserve(n);
  lit_side_.reserve(n);
  coplanar_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const PartRole role = roles[i];
    if (!receives(role)) {
      ++stats.faces_culled_range;
      if (!occludes(role)) continue;
    }
    const bool lit = role == PartRole::kFacing;
    if (role == PartRole::kTurnedAway) ++stats.faces_facing_away;
    if (receives(role)) ++stats.faces_considered;
    if (behind_solid[i] && role == PartRole::kTurnedAway) {
      ++stats.faces_behind_solids;
      continue;
    }
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

}  // namespace shadowgen::shadows::detail
