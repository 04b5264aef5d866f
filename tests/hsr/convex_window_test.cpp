// ConvexWindow: its shortcuts (beside, wholly within) give the regions the clipper gives,
// on small polygons of a coarse integer grid, where shared edges, shared corners and
// containment are the common case.

#include "hsr/convex_window.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "clipper/clip.h"
#include "clipper/predicates.h"

namespace shadowgen::hsr {
namespace {

using clipper::Loop2;
using clipper::PolygonWithHoles2;

TEST(ConvexTurn, TellsConvexLoopsAndTheirTurn) {
  EXPECT_EQ(convex_turn({{0, 0}, {2, 0}, {2, 2}, {0, 2}}), 1);
  EXPECT_EQ(convex_turn({{0, 0}, {0, 2}, {2, 2}, {2, 0}}), -1);
  EXPECT_EQ(convex_turn({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}), 1) << "straight run";
  EXPECT_EQ(convex_turn({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}), 0) << "L shape";
  EXPECT_EQ(convex_turn({{0, 0}, {2, 0}, {1, 0}, {1, 2}}), 0) << "turns back";
  EXPECT_EQ(convex_turn({{0, 0}, {2, 0}, {2, 0}, {0, 2}}), 0) << "repeated vertex";
  EXPECT_EQ(convex_turn({{0, 0}, {1, 1}, {2, 2}}), 0) << "no area";
}

bool crosses(const clipper::Point2& a, const clipper::Point2& b, const clipper::Point2& c,
             const clipper::Point2& d) {
  using clipper::orient2d;
  return orient2d(a, b, c) != orient2d(a, b, d) && orient2d(c, d, a) != orient2d(c, d, b);
}

// A random triangle or simple quadrilateral with corners on a 5 x 5 grid, convex or not,
// either orientation, no three corners on a line.
PolygonWithHoles2 random_polygon(std::mt19937& rng) {
  std::uniform_int_distribution<int> coordinate(0, 4), corners(3, 4);
  for (;;) {
    Loop2 loop;
    const int n = corners(rng);
    for (int i = 0; i < n; ++i) loop.push_back({1.0 * coordinate(rng), 1.0 * coordinate(rng)});
    bool ok = true;
    for (int i = 0; i < n; ++i) {
      ok = ok && clipper::orient2d(loop[i], loop[(i + 1) % n], loop[(i + 2) % n]) !=
                     clipper::Orientation::kCollinear;
    }
    if (n == 4) {
      ok = ok && !crosses(loop[0], loop[1], loop[2], loop[3]) &&
           !crosses(loop[1], loop[2], loop[3], loop[0]) &&
           clipper::orient2d(loop[0], loop[1], loop[3]) != clipper::Orientation::kCollinear &&
           clipper::orient2d(loop[1], loop[2], loop[0]) != clipper::Orientation::kCollinear;
    }
    if (ok) return {loop, {}};
  }
}

TEST(ConvexWindow, GivesTheClippersRegions) {
  std::mt19937 rng(7);
  int shortcuts = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const PolygonWithHoles2 window = random_polygon(rng), subject = random_polygon(rng);
    const clipper::ClipResult expected = clipper::clip(subject, window);
    const clipper::ClipResult got = ConvexWindow(window).clip(subject);
    EXPECT_NEAR(clipper::area(got.inside), clipper::area(expected.inside), 1e-12) << trial;
    EXPECT_NEAR(clipper::area(got.outside), clipper::area(expected.outside), 1e-12) << trial;
    if (got.inside.empty() != got.outside.empty()) ++shortcuts;
  }
  EXPECT_GT(shortcuts, 100);
}

// The two tests on their own say what the clip says: apart, nothing inside; held, the
// subject inside whole and nothing outside; and past the first, the rest of the clip
// gives the clipper's regions.
TEST(ConvexWindow, ApartAndHeldAreWhatTheClipSays) {
  std::mt19937 rng(11);
  int apart = 0, held = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const PolygonWithHoles2 window = random_polygon(rng), subject = random_polygon(rng);
    const ConvexWindow w(window);
    const clipper::ClipResult expected = clipper::clip(subject, window);
    if (w.apart_from(subject)) {
      ++apart;
      EXPECT_EQ(clipper::area(expected.inside), 0.0) << trial;
    }
    if (w.holds(subject)) {
      ++held;
      EXPECT_EQ(clipper::area(expected.outside), 0.0) << trial;
      EXPECT_EQ(clipper::area(expected.inside), std::fabs(clipper::area(subject))) << trial;
    }
    const std::optional<clipper::ClipResult> got = w.clip_unless_apart(subject);
    EXPECT_EQ(got.has_value(), !w.apart_from(subject)) << trial;
    if (got) {
      EXPECT_NEAR(clipper::area(got->inside), clipper::area(expected.inside), 1e-12) << trial;
      EXPECT_NEAR(clipper::area(got->outside), clipper::area(expected.outside), 1e-12) << trial;
    }
  }
  EXPECT_GT(apart, 500);
  EXPECT_GT(held, 30);
}

}  // namespace
}  // namespace shadowgen::hsr
