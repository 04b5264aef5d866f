#pragma once

// Exact geometric predicates on double coordinates.
//
// orient2d is decided exactly: a floating-point filter (Shewchuk's static bound) answers
// almost every call; when it cannot, the determinant is evaluated exactly as a
// floating-point expansion. The answer is the sign of the exact real determinant of
// the given doubles, provided no intermediate product underflows (inputs of magnitude
// above about 1e-140, or zero) or overflows (below about 1e150).

#include <glm/vec3.hpp>

#include "clipper/point.h"

namespace shadowgen::clipper {

enum class Orientation { kClockwise = -1, kCollinear = 0, kCounterClockwise = 1 };

// Sign of (b - a) x (c - a): counter-clockwise when c lies left of the line a -> b.
Orientation orient2d(const Point2& a, const Point2& b, const Point2& c);

// The determinant of orient2d itself, rounded once from its exact value: the sign is
// exact and the magnitude has a relative error below 2^-52.
double orient2d_value(const Point2& a, const Point2& b, const Point2& c);

// Sign of the determinant | a−d ; b−d ; c−d |: positive when d lies below the plane through
// a, b, c (which run counter-clockwise seen from above), zero when the four are coplanar.
// Exact in the same sense as orient2d. Used to tell exactly coplanar faces apart.
Orientation orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                     const glm::dvec3& d);

// True when p lies on the closed segment [a, b] (exact).
bool on_segment(const Point2& a, const Point2& b, const Point2& p);

}  // namespace shadowgen::clipper
