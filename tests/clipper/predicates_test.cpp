#include "clipper/predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace shadowgen::clipper {
namespace {

// Exact reference for points on the grid 2^-53 * integer: scaled to integers the
// determinant fits in 128 bits.
__extension__ using Int128 = __int128;  // a GCC/Clang extension, fine for a test

int exact_sign_on_grid(const Point2& a, const Point2& b, const Point2& c) {
  auto scaled = [](double v) { return static_cast<Int128>(std::ldexp(v, 53)); };
  const Int128 bax = scaled(b.x) - scaled(a.x), bay = scaled(b.y) - scaled(a.y);
  const Int128 cax = scaled(c.x) - scaled(a.x), cay = scaled(c.y) - scaled(a.y);
  const Int128 det = bax * cay - bay * cax;
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

// The classic failure of naive orientation (Kettner et al., "Classroom examples of
// robustness problems"): a 256x256 grid of points a few ulps around (0.5, 0.5) against
// the line through (12, 12) and (24, 24).
TEST(Orient2d, MatchesExactSignNearADegenerateLine) {
  const Point2 q{12.0, 12.0}, r{24.0, 24.0};
  int mismatches = 0, collinear = 0;
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      const Point2 p{0.5 + std::ldexp(i, -53), 0.5 + std::ldexp(j, -53)};
      const int expected = exact_sign_on_grid(p, q, r);
      const int got = static_cast<int>(orient2d(p, q, r));
      if (expected != got) ++mismatches;
      if (expected == 0) ++collinear;
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(collinear, 256);  // exactly the diagonal i == j lies on the line
}

TEST(Orient2d, ValueHasTheExactSignAndIsAccurate) {
  const Point2 a{1e8 + 0.25, 1e8}, b{1e8 + 1.25, 1e8 + 1.0};
  const Point2 on{1e8 + 2.25, 1e8 + 2.0};
  EXPECT_EQ(orient2d(a, b, on), Orientation::kCollinear);
  EXPECT_EQ(orient2d_value(a, b, on), 0.0);
  const Point2 left{1e8 + 2.25, 1e8 + 2.0 + std::ldexp(1.0, -26)};
  EXPECT_EQ(orient2d(a, b, left), Orientation::kCounterClockwise);
  EXPECT_DOUBLE_EQ(orient2d_value(a, b, left), std::ldexp(1.0, -26));
  EXPECT_EQ(orient2d(b, a, left), Orientation::kClockwise);
}

// Two of the three points the same: the determinant is exactly zero, whatever the
// coordinates (the filter's bound is zero too, so these reach the exact stage).
TEST(Orient2d, TwoPointsTheSameAreCollinear) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-1e6, 1e6);
  for (int i = 0; i < 1000; ++i) {
    const Point2 a{coordinate(rng), coordinate(rng)}, b{coordinate(rng), coordinate(rng)};
    ASSERT_EQ(orient2d(a, b, a), Orientation::kCollinear);
    ASSERT_EQ(orient2d(a, b, b), Orientation::kCollinear);
    ASSERT_EQ(orient2d(a, a, b), Orientation::kCollinear);
    ASSERT_EQ(orient2d_exact(a, b, a), Orientation::kCollinear);
  }
  // A zero of either sign is one coordinate.
  EXPECT_EQ(orient2d(Point2{0.0, 1.0}, Point2{3.0, 7.0}, Point2{-0.0, 1.0}),
            Orientation::kCollinear);
  EXPECT_EQ(orient2d_exact(Point2{1e-300, 0.0}, Point2{-0.0, 2e-300}, Point2{1e-300, -0.0}),
            Orientation::kCollinear);
  // Distinct points keep their exact answer.
  EXPECT_EQ(orient2d_exact(Point2{0.0, 0.0}, Point2{1.0, 0.0}, Point2{0.5, 0x1p-1000}),
            Orientation::kCounterClockwise);
}

// The same grid against a direction square to the line's: (12, 12) − p against
// (−12, 12), whose dot product is 12·(p.x − p.y), lost when 12 − p is rounded.
TEST(DotSign, MatchesExactSignNearARightAngle) {
  auto scaled = [](double v) { return static_cast<Int128>(std::ldexp(v, 53)); };
  const Point2 b{12.0, 12.0}, c{0.0, 0.0}, d{-12.0, 12.0};
  int mismatches = 0, perpendicular = 0;
  for (int i = 0; i < 256; ++i) {
    for (int j = 0; j < 256; ++j) {
      const Point2 a{0.5 + std::ldexp(i, -53), 0.5 + std::ldexp(j, -53)};
      const Int128 dot = (scaled(b.x) - scaled(a.x)) * (scaled(d.x) - scaled(c.x)) +
                         (scaled(b.y) - scaled(a.y)) * (scaled(d.y) - scaled(c.y));
      const int expected = dot > 0 ? 1 : (dot < 0 ? -1 : 0);
      if (dot_sign(a, b, c, d) != expected) ++mismatches;
      if (expected == 0) ++perpendicular;
      // Reversing either direction flips the sign.
      if (dot_sign(b, a, c, d) != -expected || dot_sign(a, b, d, c) != -expected) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(perpendicular, 256);  // exactly the diagonal i == j
  EXPECT_EQ(dot_sign({0.0, 0.0}, {1.0, 0.0}, {5.0, 5.0}, {5.0, 5.0}), 0);
}

TEST(OnSegment, ClosedSegmentExactly) {
  const Point2 a{0.1, 0.1}, b{0.3, 0.3};
  EXPECT_TRUE(on_segment(a, b, a));
  EXPECT_TRUE(on_segment(a, b, b));
  EXPECT_FALSE(on_segment(a, b, {0.4, 0.4}));
  EXPECT_FALSE(on_segment(a, b, {0.2, 0.2000000001}));
  const Point2 c{0.0, 0.0}, d{4.0, 2.0};
  EXPECT_TRUE(on_segment(c, d, {2.0, 1.0}));
  EXPECT_FALSE(on_segment(c, d, {2.0, std::nextafter(1.0, 2.0)}));
}

}  // namespace
}  // namespace shadowgen::clipper

namespace shadowgen::clipper {
namespace {

TEST(Orient3d, ExactOnATiltedPlaneAndOneUlpOff) {
  // The plane z = 0.5·x + 0.25·y + 1e8 holds these dyadic points exactly.
  auto on_plane = [](double x, double y) { return glm::dvec3(x, y, 0.5 * x + 0.25 * y + 1e8); };
  const glm::dvec3 a = on_plane(0, 0), b = on_plane(4, 0), c = on_plane(0, 8);
  const glm::dvec3 d = on_plane(3, 5);
  EXPECT_EQ(orient3d(a, b, c, d), Orientation::kCollinear);
  const glm::dvec3 above{d.x, d.y, std::nextafter(d.z, 2e8)};
  const glm::dvec3 below{d.x, d.y, std::nextafter(d.z, 0.0)};
  EXPECT_NE(orient3d(a, b, c, above), Orientation::kCollinear);
  EXPECT_NE(orient3d(a, b, c, below), Orientation::kCollinear);
  EXPECT_NE(orient3d(a, b, c, above), orient3d(a, b, c, below));
  // a, b, c counter-clockwise seen from above: a point below is positive.
  EXPECT_EQ(orient3d(a, b, c, below), Orientation::kCounterClockwise);
}

// A point tested against a plane through itself (faces sharing a vertex), or a plane
// through one point twice, is coplanar, whatever the rounding of the filter's products.
TEST(Orient3d, TwoPointsTheSameAreCoplanar) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> coordinate(-1e6, 1e6);
  auto point = [&] { return glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 a = point(), b = point(), c = point(), d = point();
    ASSERT_EQ(orient3d(a, b, c, a), Orientation::kCollinear);
    ASSERT_EQ(orient3d(a, b, c, b), Orientation::kCollinear);
    ASSERT_EQ(orient3d(a, b, c, c), Orientation::kCollinear);
    ASSERT_EQ(orient3d(a, a, c, d), Orientation::kCollinear);
    ASSERT_EQ(orient3d(a, b, b, d), Orientation::kCollinear);
    ASSERT_EQ(orient3d(c, b, c, d), Orientation::kCollinear);
  }
  // Distinct points a hair off the plane keep their exact answer.
  const glm::dvec3 a{0, 0, 1e8}, b{1, 0, 1e8}, c{0, 1, 1e8};
  EXPECT_EQ(orient3d(a, b, c, {0.5, 0.5, std::nextafter(1e8, 0.0)}),
            Orientation::kCounterClockwise);
}

// Four points sharing one coordinate lie on a plane square to that axis, whatever the
// others; one of them a hair off it is not.
TEST(Orient3d, OnAPlaneSquareToAnAxisIsCoplanar) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-1e6, 1e6);
  for (int i = 0; i < 1000; ++i) {
    const int axis = i % 3;
    const double level = coordinate(rng);
    auto point = [&] {
      glm::dvec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
      p[axis] = level;
      return p;
    };
    const glm::dvec3 a = point(), b = point(), c = point();
    glm::dvec3 d = point();
    ASSERT_EQ(orient3d(a, b, c, d), Orientation::kCollinear);
    d[axis] = std::nextafter(level, 2e6);
    ASSERT_NE(orient3d(a, b, c, d), Orientation::kCollinear);
  }
}

}  // namespace
}  // namespace shadowgen::clipper

namespace shadowgen::clipper {
namespace {

// The midpoint predicates against the same 128-bit reference: on the grid 2^-53·k,
// 2m = a + b and 2·(q − p) x (m − p) = (q − p) x (a + b − 2p) are integers.
int exact_midpoint_orientation_on_grid(const Point2& p, const Point2& q, const Midpoint2& m) {
  auto scaled = [](double v) { return static_cast<Int128>(std::ldexp(v, 53)); };
  const Int128 dx = scaled(q.x) - scaled(p.x), dy = scaled(q.y) - scaled(p.y);
  const Int128 sx = scaled(m.a.x) + scaled(m.b.x) - 2 * scaled(p.x);
  const Int128 sy = scaled(m.a.y) + scaled(m.b.y) - 2 * scaled(p.y);
  const Int128 det = dx * sy - dy * sx;
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

// Midpoints of pairs of points a few ulps around (0.5, 0.5) against the diagonal through
// (12, 12) and (24, 24): every midpoint lies on it, half of them half an ulp from any
// double, and the other pairs' midpoints off it by half an ulp.
TEST(Orient2dMidpoint, MatchesExactSignNearADegenerateLine) {
  const Point2 p{12.0, 12.0}, q{24.0, 24.0};
  int mismatches = 0, collinear = 0, unrepresentable_collinear = 0;
  for (int i = 0; i < 32; ++i) {
    for (int j = 0; j < 32; ++j) {
      const Point2 a{0.5 + std::ldexp(i, -53), 0.5 + std::ldexp(j, -53)};
      const Point2 b{0.5 + std::ldexp(j, -53), 0.5 + std::ldexp(i, -53)};
      const Midpoint2 m{a, b};
      const int expected = exact_midpoint_orientation_on_grid(p, q, m);
      if (expected != static_cast<int>(orient2d(p, q, m))) ++mismatches;
      const Midpoint2 off{a, {b.x + std::ldexp(1.0, -53), b.y}};
      if (exact_midpoint_orientation_on_grid(p, q, off) != static_cast<int>(orient2d(p, q, off))) {
        ++mismatches;
      }
      if (expected == 0) {
        ++collinear;
        if ((i + j) % 2 != 0) ++unrepresentable_collinear;
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(collinear, 32 * 32);  // (i + j) / 2 ulps in both coordinates: on the diagonal
  EXPECT_GT(unrepresentable_collinear, 0);
}

TEST(Orient2dMidpoint, SidesOffTheLineAndFarFromTheOrigin) {
  const Point2 p{1e8, 1e8}, q{1e8 + 4.0, 1e8 + 2.0};
  // (p + q) / 2 lies on the line; one ulp either way in y moves the midpoint half an ulp.
  const double up = std::nextafter(1e8 + 2.0, 2e8), down = std::nextafter(1e8 + 2.0, 0.0);
  EXPECT_EQ(orient2d(p, q, Midpoint2{p, q}), Orientation::kCollinear);
  EXPECT_EQ(orient2d(p, q, Midpoint2{p, {q.x, up}}), Orientation::kCounterClockwise);
  EXPECT_EQ(orient2d(p, q, Midpoint2{p, {q.x, down}}), Orientation::kClockwise);
}

TEST(CompareMidpoint, ExactWhereTheMidpointIsNoDouble) {
  const double x = 3461825.89;
  const double next = std::nextafter(x, 4e6);
  const Midpoint2 m{{x, 0.0}, {next, 1.0}};  // m.x is half an ulp above x: no double
  EXPECT_EQ(compare_x(m, x), 1);
  EXPECT_EQ(compare_x(m, next), -1);
  EXPECT_EQ(compare_x(Midpoint2{{x, 0.0}, {x, 1.0}}, x), 0);
  EXPECT_EQ(compare_y(m, 0.5), 0);
  EXPECT_EQ(compare_y(m, std::nextafter(0.5, 1.0)), -1);
  EXPECT_EQ(compare_y(Midpoint2{{0.0, 1e300}, {0.0, 1e300}}, 1e300), 0);
}

// The crossing of the diagonal e with the segment f lies on a known point; the line g
// through it, and one ulp beside it, tell the predicate's three answers apart.
TEST(Orient2dCrossing, SideOfALineThroughTheExactCrossing) {
  const Point2 e0{0.0, 0.0}, e1{3.0, 3.0};  // y = x
  const Point2 f0{0.0, 2.0}, f1{2.0, 0.0};  // x + y = 2: crosses e at (1, 1)
  const Point2 g0{1.0, -5.0};
  EXPECT_EQ(orient2d_crossing(g0, {1.0, 7.0}, e0, e1, f0, f1), Orientation::kCollinear);
  const double right = std::nextafter(1.0, 2.0), left = std::nextafter(1.0, 0.0);
  // The line x = 1 + ulp, going up: (1, 1) lies to its left.
  EXPECT_EQ(orient2d_crossing({right, -5.0}, {right, 7.0}, e0, e1, f0, f1),
            Orientation::kCounterClockwise);
  EXPECT_EQ(orient2d_crossing({left, -5.0}, {left, 7.0}, e0, e1, f0, f1), Orientation::kClockwise);
  // Independent of the direction of e and f.
  EXPECT_EQ(orient2d_crossing({left, -5.0}, {left, 7.0}, e1, e0, f1, f0), Orientation::kClockwise);
}

// A crossing that is no double: e: y = x/3 crosses f: x = 1 at (1, 1/3). The line
// y = 1/3 rounded down passes below it, rounded up above it.
TEST(Orient2dCrossing, ExactWhereTheCrossingIsNoDouble) {
  const Point2 e0{0.0, 0.0}, e1{3.0, 1.0}, f0{1.0, -1.0}, f1{1.0, 1.0};
  const double third = 1.0 / 3.0;  // below 1/3
  const double above = std::nextafter(third, 1.0);
  EXPECT_EQ(orient2d_crossing({0.0, third}, {2.0, third}, e0, e1, f0, f1),
            Orientation::kCounterClockwise);
  EXPECT_EQ(orient2d_crossing({0.0, above}, {2.0, above}, e0, e1, f0, f1), Orientation::kClockwise);
}

}  // namespace
}  // namespace shadowgen::clipper
