#include "clipper/detail/crossing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "clipper/predicates.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen::clipper::detail {
namespace {

constexpr double kBound = 5.0 * 0x1p-53;  // crossing.h: 5u of each coordinate's magnitude

bool properly_crossing(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1) {
  auto side = [](const Point2& p, const Point2& q, const Point2& r) {
    return static_cast<int>(orient2d(p, q, r));
  };
  return side(a0, a1, b0) * side(a0, a1, b1) < 0 && side(b0, b1, a0) * side(b0, b1, a1) < 0;
}

// Crossing pairs of segments of length about `length` around `centre` (spread by
// `spread`), at random angles: each result within the bound of the exact crossing, and
// the same point bit for bit whichever segment comes first and whichever way each runs.
void expect_within_bound(std::mt19937_64& rng, Point2 centre, double spread, double length,
                         int pairs) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0), angle(0.0, 6.283185307179586);
  int tried = 0;
  for (int found = 0; found < pairs && tried < 50 * pairs; ++tried) {
    const Point2 at{centre.x + spread * unit(rng), centre.y + spread * unit(rng)};
    auto segment = [&](Point2& s0, Point2& s1) {
      const double a = angle(rng), f = 0.5 + 0.5 * unit(rng);
      s0 = {at.x - f * length * std::cos(a), at.y - f * length * std::sin(a)};
      s1 = {at.x + (1.0 - f) * length * std::cos(a), at.y + (1.0 - f) * length * std::sin(a)};
    };
    Point2 a0, a1, b0, b1;
    segment(a0, a1);
    segment(b0, b1);
    if (!properly_crossing(a0, a1, b0, b1)) continue;
    ++found;
    const Point2 p = crossing_point(a0, a1, b0, b1);
    ASSERT_TRUE(test::near_exact_crossing(p, a0, a1, b0, b1, kBound))
        << "centre (" << centre.x << ", " << centre.y << "), length " << length << ": (" << a0.x
        << ", " << a0.y << ")-(" << a1.x << ", " << a1.y << ") x (" << b0.x << ", " << b0.y << ")-("
        << b1.x << ", " << b1.y << ") gave (" << p.x << ", " << p.y << ")";
    ASSERT_EQ(crossing_point(b1, b0, a0, a1), p);
    ASSERT_EQ(crossing_point(a1, a0, b1, b0), p);
  }
  EXPECT_GT(tried, 0);
}

TEST(CrossingPoint, ShortEdgesAwayFromTheAxes) {
  std::mt19937_64 rng(11);
  expect_within_bound(rng, {1000.0, 700.0}, 200.0, 20.0, 2000);
  expect_within_bound(rng, {-3e6, 2e6}, 1e5, 50.0, 2000);
}

// Where one coordinate is small beside the other (a city's streets along an axis of the
// light's image), or the edges are long beside the coordinates: the step along the
// shorter segment is not small beside both coordinates, and the exact construction
// takes over.
TEST(CrossingPoint, NearTheAxesAndAlongLongEdges) {
  std::mt19937_64 rng(12);
  expect_within_bound(rng, {1000.0, 3.0}, 5.0, 20.0, 2000);
  expect_within_bound(rng, {0.5, -2000.0}, 1.0, 20.0, 2000);
  expect_within_bound(rng, {0.0, 0.0}, 1.0, 3.0, 2000);
  expect_within_bound(rng, {1000.0, 700.0}, 200.0, 5e4, 2000);
}

TEST(CrossingPoint, AtTheExtremesOfTheCoordinateRange) {
  std::mt19937_64 rng(13);
  expect_within_bound(rng, {3e60, -1e60}, 1e59, 1e57, 500);
  expect_within_bound(rng, {3e-60, -1e-60}, 1e-61, 1e-62, 500);
  expect_within_bound(rng, {1e-40, 1e40}, 1e-41, 1e39, 500);
}

}  // namespace
}  // namespace shadowgen::clipper::detail
