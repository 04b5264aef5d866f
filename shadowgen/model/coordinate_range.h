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

namespace shadowgen {

inline constexpr double kLargestCoordinate = 1e100;
inline constexpr double kSmallestExtent = 1e-100;

}  // namespace shadowgen
