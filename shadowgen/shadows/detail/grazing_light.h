#pragma once

// Faces that a light grazes: their lit regions worked out in their own plane.
//
// Hidden-surface removal sees a face at angle θ to the light's rays as an image sin θ
// times as wide as the face, and casting image points back onto the face divides their
// rounding by sin θ. Below sin θ = 2^-20 that rounding, 2^-52 of the coordinates, grows
// past 2^-32 of them on the face (the oracle suite's bound is 1e-9 of a face's area), and
// at 1e-17 it swamps the face: a lit wedge vanishes. For such faces the lit region is
// taken straight from its definition (scene-format.md), in the face's plane chart: the
// face less the shadow of every other polygon, projected onto the plane from the light.
// For a point light sin θ is its height over the face's plane over its distance to the
// face's farthest vertex (the smallest angle at which a ray meets the face).
//
// Only an occluder's part between the face's plane and the light casts a shadow: heights
// 0 < h < slab, with slab the light's own height for a point light, and for a directional
// one the height beyond which a shadow lands more than twice the size of face and
// occluder together away (2^30 of that size times sin θ is used, a safe margin). The slab
// can be far thinner than a rounding of the occluder's coordinates (a sun 1e-40 from
// grazing), so the occluder is charted in coordinates where it is not: s along the line
// where its plane meets the face's, and a level across the slab. For a directional light
// the level is t = h / slab, cut to 0 <= t <= 1, and the projection affine in (s, t). For
// a point light it is u = (slab − h) / slab, taken from the lamp's own height above each
// point, so that points a hair below the lamp's height, whose shadows reach 1/u of their
// distance from it, keep their precision; u is cut to u_min <= u <= 1, u_min small enough
// that the cut's shadow lies beyond the face's box (twice over), so a shadow reaches the
// face's edge however many times farther than its occluder that is (a box a hair below a
// lamp 1e-66 in size, its shadow on a ground 1e63 wide). The cut is Sutherland–Hodgman on
// the two levels (the clipper would snap a level 1e-20 beside an s of 1 to 0), and every
// piece is projected vertex by vertex (the projection maps lines to lines). Shadows are
// cut to the face's box before the difference; the crossing points of that cut are
// accurate to the short edge's length (clip.h).

#include <span>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::shadows::detail {

// How `light` meets the front side of `part`, in `plane`, by sin θ:
//   kInPlane  sin θ = 0: a point light in the plane, a directional one parallel to it.
//             The plane's own test of which side a light is on (faces_light) can still
//             put it in front by a rounding; seen edge-on, the part would then be cast
//             back from an image without width. A light in the plane leaves the part
//             unlit (scene-format.md).
//   kGrazing  0 < sin θ < 2^-20: lit by lit_by_grazing_light.
//   kOpen     otherwise: lit through the light's views.
enum class Incidence { kInPlane, kGrazing, kOpen };
Incidence incidence(const hsr::Polygon3& part, const hsr::Plane3& plane, const Light& light);

// The lit region of polygons[part] under `light`, which must reach its front side.
// `coplanar[i]`: polygons[i]'s coplanar group (coplanar_groups.h, -1 for none); members
// of the part's group cast no shadow on it. Outer loops counter-clockwise seen from the
// side the plane's normal points to; the part's own vertices are passed through unchanged.
std::vector<hsr::Polygon3> lit_by_grazing_light(std::size_t part,
                                                std::span<const hsr::Polygon3> polygons,
                                                std::span<const hsr::Plane3> planes,
                                                std::span<const int> coplanar, const Light& light);

}  // namespace shadowgen::shadows::detail
