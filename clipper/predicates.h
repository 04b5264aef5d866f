#pragma once

// Exact geometric predicates on double coordinates.
//
// orient2d is decided exactly: a floating-point filter (Shewchuk's static bound) answers
// almost every call; when it cannot, the determinant is evaluated exactly as a
// floating-point expansion. The answer is the sign of the exact real determinant of
// the given doubles, provided no intermediate product underflows (inputs of magnitude
// above about 1e-140, or zero) or overflows (below about 1e150).

#include <cmath>
#include <glm/vec3.hpp>

#include "clipper/point.h"

namespace shadowgen::clipper {

enum class Orientation { kClockwise = -1, kCollinear = 0, kCounterClockwise = 1 };

// Sign of (b - a) x (c - a): counter-clockwise when c lies left of the line a -> b.
// Inline: the clipper asks it millions of times, nearly always settled by the filter.
inline Orientation orient2d(const Point2& a, const Point2& b, const Point2& c);

// orient2d's answer from the exact determinant, where its filter cannot tell.
Orientation orient2d_exact(const Point2& a, const Point2& b, const Point2& c);

// The determinant of orient2d itself, rounded once from its exact value: the sign is
// exact and the magnitude has a relative error below 2^-52.
double orient2d_value(const Point2& a, const Point2& b, const Point2& c);

// Sign of the dot product (b − a)·(d − c): 1 when the two directions are less than a
// right angle apart, -1 when more, 0 when perpendicular (or either is zero). Exact in
// the same sense as orient2d.
int dot_sign(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

// Sign of the determinant | a−d ; b−d ; c−d |: positive when d lies below the plane through
// a, b, c (which run counter-clockwise seen from above), zero when the four are coplanar.
// Exact in the same sense as orient2d. Used to tell exactly coplanar faces apart.
Orientation orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                     const glm::dvec3& d);

// True when p lies on the closed segment [a, b] (exact).
bool on_segment(const Point2& a, const Point2& b, const Point2& p);

// Which side of the line g0 -> g1 the exact crossing point of the segments e0-e1 and
// f0-f1 lies on, without constructing it. The segments must cross properly (each
// strictly separates the other's endpoints). Exact in the same sense as orient2d, for
// coordinates of magnitude up to about 1e75 (it multiplies pairs of determinants).
Orientation orient2d_crossing(const Point2& g0, const Point2& g1, const Point2& e0,
                              const Point2& e1, const Point2& f0, const Point2& f1);

// The crossing point of the segments a0-a1 and b0-b1, which must cross properly (each
// strictly separates the other's endpoints), from exact determinants: each coordinate
// within 5u of its own magnitude of the exact one (u = 2^-53), however long the
// segments. For coordinates up to about 1e75 (it multiplies determinants by coordinates).
Point2 crossing_point_exact(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1);

// The midpoint m = (a + b) / 2 of two points, held exactly. Rounded to doubles, m can
// land an ulp off the segment [a, b], across a boundary that runs within an ulp of it
// (a sliver between two nearly collinear edges); these predicates decide for m itself.
struct Midpoint2 {
  Point2 a;
  Point2 b;
};

// Signs of m.x − x and m.y − y: -1, 0 or 1, exact.
int compare_x(const Midpoint2& m, double x);
int compare_y(const Midpoint2& m, double y);

// Sign of (q - p) x (m - p), exact in the same sense as orient2d.
Orientation orient2d(const Point2& p, const Point2& q, const Midpoint2& m);

// Shewchuk's ccwerrboundA: when |det| exceeds this times the permanent, the rounded
// determinant of orient2d has the exact sign.
inline constexpr double kOrient2dBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;

inline Orientation orient2d(const Point2& a, const Point2& b, const Point2& c) {
  const double left = (b.x - a.x) * (c.y - a.y);
  const double right = (b.y - a.y) * (c.x - a.x);
  const double det = left - right;
  const double bound = kOrient2dBound * (std::fabs(left) + std::fabs(right));
  if (det > bound) return Orientation::kCounterClockwise;
  if (-det > bound) return Orientation::kClockwise;
  return orient2d_exact(a, b, c);
}

}  // namespace shadowgen::clipper
