#pragma once

// What one light makes of each part of the scene (docs/scene-format.md, "Lights" and
// "What lit means"): the rules that decide which parts it takes into account at all and
// which of those it can light, shared by the exact generator (detail/receivers.h) and the
// sampled estimators (shadowgen/sampled/), so that both answer the same question.
//
//   - A point light's range.end leaves out every part wholly beyond it as a receiver. Such
//     a part still shadows the receivers it stands in front of (the spec: a face inside the
//     range gets its whole lit region, the shadows of occluders beyond range.end included),
//     so it is kept as an occluder when it is nearer to the light than some receiver's
//     farthest vertex, and only dropped where it cannot stand between the light and any
//     receiver.
//   - A receiver whose front side faces away from the light, or sees it edge-on (the light
//     in its plane, a directional light parallel to it), or that has no plane (no area),
//     gets no lit area, and still occludes.

#include <cstddef>
#include <span>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen {

enum class PartRole : unsigned char {
  kLeftOut,     // beyond range.end and farther than every receiver: neither receives nor occludes
  kOccluder,    // beyond range.end, near enough to shadow a receiver: occludes, receives nothing
  kTurnedAway,  // a receiver the light does not reach the front side of: lit area 0, occludes
  kFacing,      // a receiver whose front side faces the light
};

// Whether the part receives the light (it may still get no lit area: kTurnedAway).
inline bool receives(PartRole role) {
  return role == PartRole::kTurnedAway || role == PartRole::kFacing;
}
// Whether the part stands in the light's way: everything but kLeftOut.
inline bool occludes(PartRole role) { return role != PartRole::kLeftOut; }

// Every part of every face of a scene, face by face, with its plane (hsr::plane_of): what
// part_roles takes. Face f's parts are [first[f], first[f + 1]).
struct ScenePartPlanes {
  std::vector<hsr::Polygon3> polygons;
  std::vector<hsr::Plane3> planes;
  std::vector<std::size_t> first{0};

  explicit ScenePartPlanes(const Scene& scene);
  std::size_t index(std::size_t face, std::size_t part) const { return first[face] + part; }
};

// The role of every part under `light`; `planes` are the parts' hsr::plane_of, in parallel.
std::vector<PartRole> part_roles(std::span<const hsr::Polygon3> polygons,
                                 std::span<const hsr::Plane3> planes, const Light& light);

}  // namespace shadowgen
