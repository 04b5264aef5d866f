#pragma once

// The coordinates shadowgen supports (docs/scene-format.md, "Numbers").
//
// Every coordinate of a face, a light's position and a view's eye and target has a
// magnitude of at most kLargestCoordinate, and every face whose vertices are not all one
// point spans at least kSmallestExtent (the largest side of its bounding box). Inside
// that range the products that areas and planes are made of (coordinate differences
// squared, from 1e-200 to about 1e201) are normal doubles, so no area overflows to inf or
// underflows to 0; outside it the readers refuse the input rather than answer with inf,
// nan or a silent 0.
//
// A point light sees through views whose near distance is half the least depth a point
// of its nearest face can have (lamp_near_distance): its distance over √3, so no face is
// cut off. That distance is never taken below kLampNearFloor = 2^-450 of the farthest
// vertex's distance, so that image coordinates, which reach farthest / near beside the
// light, keep finite squares (below 2^900; the clipper's determinants multiply two of
// them). Where the nearest face is nearer than the floor allows (lamp_depths_supported:
// nearest at least 2√3 × 2^-450 ≈ 1.19e-135 of farthest), the near plane would cut faces
// off, lighting what they hide and hiding what they light: a lamp 1e-74 above a face of
// 1e-68 in a scene 1e68 wide. The scene reader refuses such a light.

#include <algorithm>
#include <cmath>

namespace shadowgen {

inline constexpr double kLargestCoordinate = 1e100;
inline constexpr double kSmallestExtent = 1e-100;
inline constexpr double kLampNearFloor = 0x1p-450;

// The near distance of a point light's views, from the distances of its nearest face and
// its farthest vertex (shadows/light_views.h).
inline double lamp_near_distance(double nearest, double farthest) {
  return std::max(0.5 * nearest / std::sqrt(3.0), kLampNearFloor * farthest);
}

// Whether lamp_near_distance is the nearest face's own, the floor cutting nothing off.
inline bool lamp_depths_supported(double nearest, double farthest) {
  return 0.5 * nearest / std::sqrt(3.0) >= kLampNearFloor * farthest;
}

}  // namespace shadowgen
