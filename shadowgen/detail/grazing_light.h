#pragma once

// Faces that a directional light grazes: their lit regions worked out in their own plane.
//
// Hidden-surface removal sees a face at angle θ to the light as an image sin θ times as
// wide as the face, and casting image points back onto the face divides their rounding
// by sin θ. Below sin θ = 2^-20 that rounding, 2^-52 of the coordinates, grows past 2^-32
// of them on the face (the oracle suite's bound is 1e-9 of a face's area), and at 1e-17
// it swamps the face: a lit wedge vanishes. For such faces the lit region is taken
// straight from its definition (scene-format.md), in the face's plane chart: the face less
// the shadow of every other polygon, projected onto the plane along the light.
//
// Projection along a grazing light sends points at height h in front of the plane a
// distance h / sin θ away. An occluder is first cut to the front half-space (its part
// behind the plane casts nothing) and to a slab 2^30 × (the size of the face and the
// occluder together) × sin θ high, beyond which its shadow cannot come back within the
// face; the shadow is cut to the face's box before the difference. The crossing points
// of that cut are accurate to the short edge's length (clip.h), so huge shadow polygons
// cost no precision near the face.

#include <span>
#include <vector>

#include "hsr/polygon3.h"

namespace shadowgen::detail {

// Whether the light along `direction` (not normalised) grazes `plane`: 0 < sin θ < 2^-20.
bool grazes(const hsr::Plane3& plane, const glm::dvec3& direction);

// The lit region of polygons[part] under the directional light along `direction`, which
// must reach its front side. `coplanar[i]`: polygons[i]'s coplanar group (coplanar_groups.h,
// -1 for none); members of the part's group cast no shadow on it. Outer loops
// counter-clockwise seen from the side the plane's normal points to; the part's own
// vertices are passed through unchanged.
std::vector<hsr::Polygon3> lit_by_grazing_light(std::size_t part,
                                                std::span<const hsr::Polygon3> polygons,
                                                std::span<const hsr::Plane3> planes,
                                                std::span<const int> coplanar,
                                                const glm::dvec3& direction);

}  // namespace shadowgen::detail
