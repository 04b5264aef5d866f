// Snap rounding of both operands (clipper/detail/snap_rounding.h): every meeting point
// becomes a vertex of both boundaries, and afterwards no two edges cross.

#include "clipper/detail/snap_rounding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "clipper/predicates.h"
#include "tests/clipper/snap_shortcut_check.h"
#include "tests/support/random_polygons.h"
#include "tests/support/transform.h"

namespace shadowgen::clipper::detail {
namespace {

bool has(const Loop2& loop, const Point2& p) {
  return std::find(loop.begin(), loop.end(), p) != loop.end();
}

// No two edges of all the loops cross properly.
bool noded(const std::vector<Loop2> (&loops)[2]) {
  std::vector<std::pair<Point2, Point2>> edges;
  for (const auto& side : loops) {
    for (const Loop2& l : side) {
      for (std::size_t i = 0; i < l.size(); ++i) edges.emplace_back(l[i], l[(i + 1) % l.size()]);
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto& [a0, a1] = edges[i];
      const auto& [b0, b1] = edges[j];
      const Orientation p = orient2d(a0, a1, b0), q = orient2d(a0, a1, b1);
      const Orientation r = orient2d(b0, b1, a0), s = orient2d(b0, b1, a1);
      if (p != Orientation::kCollinear && q != Orientation::kCollinear && p != q &&
          r != Orientation::kCollinear && s != Orientation::kCollinear && r != s) {
        return false;
      }
    }
  }
  return true;
}

TEST(SnapRound, CrossingsBecomeVerticesOfBoth) {
  std::vector<Loop2> loops[2] = {{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}},
                                 {{{2, 2}, {6, 2}, {6, 6}, {2, 6}}}};
  SnapRoundingStats stats;
  snap_round(loops, &stats);
  EXPECT_TRUE(stats.converged);
  EXPECT_EQ(stats.crossings, 2u);
  for (const auto& side : loops) {
    EXPECT_TRUE(has(side[0], {4, 2}));
    EXPECT_TRUE(has(side[0], {2, 4}));
  }
  EXPECT_EQ(loops[0][0].size(), 6u);
  EXPECT_EQ(loops[1][0].size(), 6u);
  EXPECT_TRUE(noded(loops));
}

TEST(SnapRound, VertexOnAnEdgeSplitsItAndNothingIsConstructed) {
  std::vector<Loop2> loops[2] = {{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, {{{2, 0}, {3, -2}, {1, -2}}}};
  SnapRoundingStats stats;
  snap_round(loops, &stats);
  EXPECT_EQ(stats.crossings, 0u);
  EXPECT_TRUE(has(loops[0][0], {2, 0}));
  EXPECT_EQ(loops[1][0].size(), 3u);
}

// A vertex an ulp off an edge lies in its hot pixel (snap.h: 12u of each coordinate's
// magnitude, 1.3e-15 at y = 1): the edge is routed through it. One 1e-9 off is a feature
// and stays apart.
TEST(SnapRound, VertexInThePixelIsRoutedThroughFartherOneIsNot) {
  const double just_below = std::nextafter(1.0, 0.0);
  std::vector<Loop2> loops[2] = {
      {{{-4, 1}, {4, 1}, {4, 5}, {-4, 5}}},
      {{{1, just_below}, {2, -3}, {0, -3}}, {{-1, 1 - 1e-9}, {-2, -3}, {-3, -3}}}};
  snap_round(loops);
  EXPECT_TRUE(has(loops[0][0], {1, just_below}));
  EXPECT_FALSE(has(loops[0][0], {-1, 1 - 1e-9}));
  EXPECT_TRUE(noded(loops));
}

// Crossings of one long edge less than a rounding apart keep the order of their exact
// points (tests/clipper/regressions/crossings-swapped-along-a-long-edge-by-x-rounding.wkt
// has the clip that lost everything when they did not): the result is noded.
TEST(SnapRound, LongEdgeAcrossANeedleBesideTheAxisEndsNoded) {
  std::vector<Loop2> loops[2] = {{{{0, -8}, {-8, -7.9999999880083124}, {780131328, -8}}},
                                 {{{479534592, 0}, {0, 0}, {0, -243383296}}}};
  SnapRoundingStats stats;
  snap_round(loops, &stats);
  EXPECT_TRUE(stats.converged);
  EXPECT_TRUE(noded(loops));
}

// The shortcut (operands clear of each other but where edges cross or a vertex lies in an
// edge's way) gives the loops and statistics the rounds give, on random pairs of doubles,
// on a coarse integer grid (shared edges, vertices on edges and on vertices), on slivers,
// far from the origin, and on a grid polygon against itself moved a hair (its vertices a
// pixel or a few from its own edges, mostly left to the rounds). Both ways are taken
// often.
// A star of `points` spikes around `centre`, its radii random between half and all of
// `radius`: dozens of edges, crossing another such star's many times.
PolygonWithHoles2 random_star(std::mt19937_64& rng, int points, Point2 centre, double radius) {
  std::uniform_real_distribution<double> spread(0.5, 1.0);
  PolygonWithHoles2 star;
  for (int k = 0; k < points; ++k) {
    const double angle = 6.283185307179586 * k / points, r = radius * spread(rng);
    star.outer.push_back({centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)});
  }
  return star;
}

TEST(SnapRound, TheShortcutGivesWhatTheRoundsGive) {
  std::mt19937_64 rng(0x5eed5c07);
  int taken = 0, declined = 0, taken_past_one_mask = 0;
  std::uniform_int_distribution<int> spikes(20, 60);
  for (int trial = 0; trial < 3000; ++trial) {
    const int family = trial % 5;
    auto make = [&]() -> PolygonWithHoles2 {
      if (family == 0) return test::random_polygon_with_holes(rng);
      if (family == 1 || family == 3) return test::random_grid_polygon(rng);
      if (family == 4) return random_star(rng, spikes(rng), {trial % 7 * 0.1, 0.3}, 1.0);
      return test::sliver_triangle(rng, 1e6);
    };
    PolygonSet2 subject{make()}, clip{family == 2 ? test::random_grid_polygon(rng) : make()};
    if (trial % 2 == 1) {
      subject = test::translated(subject, {1e6, -3e6});
      clip = test::translated(clip, {1e6, -3e6});
    }
    if (family == 3) {
      const double hair = trial % 2 == 1 ? 1e-9 : 3e-15;  // a few ulps of the coordinates
      clip = test::translated(subject, {hair, -hair});
    }
    bool shortcut = false;
    EXPECT_EQ(test::shortcut_disagreement(subject, clip, &shortcut), "") << "trial " << trial;
    ++(shortcut ? taken : declined);
    // The shortcut's masks hold 64 edges each: pairs of more than that cross from one to
    // the next.
    if (shortcut && vertex_count(subject) + vertex_count(clip) > 64) ++taken_past_one_mask;
  }
  EXPECT_GT(taken, 1000);
  EXPECT_GT(declined, 300);
  EXPECT_GT(taken_past_one_mask, 100);
}

}  // namespace
}  // namespace shadowgen::clipper::detail
