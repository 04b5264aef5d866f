// Snap rounding on a grid (clipper/detail/grid_snap.h), the snapping's last resort: the
// cells' half-open rule, the exact meeting of an edge and a cell, groups snapped on their
// own grids, and clips made through it alone held against CGAL.

#include "clipper/detail/grid_snap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "clipper/clip.h"
#include "clipper/detail/snap_convergence.h"
#include "clipper/detail/snap_rounding.h"
#include "clipper/normalize.h"
#include "tests/support/clip_check.h"
#include "tests/support/random_polygons.h"
#include "tests/support/wkt.h"

namespace shadowgen::clipper::detail {
namespace {

// Largest magnitudes in (2^49, 2^50] make the grid's width 1 (the least power of two of
// at least 8u·M), with cells [i − ½, i + ½) around the integers; doubles there are
// spaced 1/8.
constexpr double kB = 0x1p50 - 64.0;

TEST(GridSnap, AVertexOnACellsSideGoesToTheCellAboveOrRight) {
  std::vector<Loop2> loops[2] = {
      {{{kB + 0.5, kB + 0.5}, {kB + 10.25, kB}, {kB, kB + 10.375}}},
      {{{-kB - 0.5, -kB - 0.5}, {-kB - 10.25, -kB}, {-kB, -kB - 10.625}}}};
  snap_round_on_grid(loops);
  EXPECT_EQ(loops[0][0], (Loop2{{kB + 1, kB + 1}, {kB + 10, kB}, {kB, kB + 10}}));
  // Below zero too: -B - ½ lies on the side between -B - 1 and -B, and goes up to -B.
  EXPECT_EQ(loops[1][0], (Loop2{{-kB, -kB}, {-kB - 10, -kB}, {-kB, -kB - 11}}));
}

// The diagonal from (B, B) to (B + 3, B + 3) touches the cell of (B + 1, B) at one corner,
// (B + ½, B + ½), which belongs to the cell of (B + 1, B + 1): it does not meet that cell,
// though the cell is hot, and keeps its straight course. An edge the other way through
// the same corner meets the cells on either side of it and the corner's own.
TEST(GridSnap, AnEdgeThroughACornerMeetsTheCellsThatHoldItsPoints) {
  const Loop2 diagonal = {{kB, kB}, {kB + 3, kB + 3}, {kB, kB + 3}};
  const Loop2 beside = {{kB + 1, kB - 0.25}, {kB + 6, kB - 3}, {kB + 6, kB - 4}};
  std::vector<Loop2> loops[2] = {{diagonal}, {beside}};
  snap_round_on_grid(loops);
  EXPECT_EQ(loops[0][0], diagonal);
  EXPECT_EQ(loops[1][0], (Loop2{{kB + 1, kB}, {kB + 6, kB - 3}, {kB + 6, kB - 4}}));

  // From (B + 2, B - 1) to (B - 1, B + 2) through the corner: the cells of (B + 1, B) and
  // (B, B + 1) hold its points on either side, the corner's cell its one point there.
  const Loop2 across = {{kB + 2, kB - 1}, {kB - 1, kB + 2}, {kB - 1, kB - 1}};
  const Loop2 marks = {{kB + 1, kB + 1.25}, {kB + 1.25, kB + 1}, {kB + 5, kB + 5}};
  std::vector<Loop2> through[2] = {{across}, {marks}};
  snap_round_on_grid(through);
  EXPECT_EQ(through[0][0],
            (Loop2{{kB + 2, kB - 1}, {kB + 1, kB + 1}, {kB - 1, kB + 2}, {kB - 1, kB - 1}}));
}

// A crossing's cell is hot, and both edges pass through its centre.
TEST(GridSnap, BothEdgesPassThroughTheCentreOfTheirCrossingsCell) {
  std::vector<Loop2> loops[2] = {{{{kB, kB}, {kB + 8, kB + 0.25}, {kB + 8, kB + 8}}},
                                 {{{kB + 4, kB - 4}, {kB + 4.25, kB + 4}, {kB - 4, kB + 4}}}};
  snap_round_on_grid(loops);
  const Point2 centre{kB + 4, kB};
  EXPECT_NE(std::find(loops[0][0].begin(), loops[0][0].end(), centre), loops[0][0].end());
  EXPECT_NE(std::find(loops[1][0].begin(), loops[1][0].end(), centre), loops[1][0].end());
  EXPECT_TRUE(noded(loops));
}

// Loops far from each other are snapped on grids of their own magnitudes: a square of
// 1e-9 near the origin moves by less than its own pixels beside loops near 1e8 (whose
// grid would make it a point), and a loop snapped to a single cell vanishes.
TEST(GridSnap, LoopsApartAreSnappedOnTheirOwnGrids) {
  const Loop2 small = {{1e-9, 1e-9}, {2e-9, 1e-9}, {2e-9, 2e-9}, {1e-9, 2e-9}};
  const Loop2 speck = {{1e8, 1e8}, {1e8 + 1.5e-8, 1e8}, {1e8, 1e8 + 1.5e-8}};
  std::vector<Loop2> loops[2] = {{small, speck},
                                 {{{1e8 + 1, 1e8}, {1e8 + 2, 1e8}, {1e8 + 2, 1e8 + 1}}}};
  snap_round_on_grid(loops);
  ASSERT_EQ(loops[0][0].size(), small.size());
  for (std::size_t i = 0; i < small.size(); ++i) {
    EXPECT_LE(std::fabs(loops[0][0][i].x - small[i].x), 12 * 0x1p-53 * 2e-9);
    EXPECT_LE(std::fabs(loops[0][0][i].y - small[i].y), 12 * 0x1p-53 * 2e-9);
  }
  EXPECT_TRUE(loops[0][1].empty());
  EXPECT_EQ(loops[1][0], (Loop2{{1e8 + 1, 1e8}, {1e8 + 2, 1e8}, {1e8 + 2, 1e8 + 1}}));
}

// The input the rounds could not settle either way (regression
// rounds-cycling-in-a-cluster-of-ulps-near-1e8): the grid nodes it, and only there does
// the snapping take the grid.
TEST(GridSnap, TakenWhereTheRoundsCycleAndNowhereElse) {
  std::ifstream in(std::string(SHADOWGEN_REGRESSION_DIR) +
                   "/rounds-cycling-in-a-cluster-of-ulps-near-1e8.wkt");
  ASSERT_TRUE(in);
  std::vector<PolygonSet2> operands;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') operands.push_back(test::read_wkt(line).polygons);
  }
  ASSERT_EQ(operands.size(), 2u);
  std::vector<Loop2> loops[2];
  for (int side = 0; side < 2; ++side) {
    for (const PolygonWithHoles2& p : normalized(operands[side])) {
      loops[side].push_back(p.outer);
      for (const Loop2& h : p.holes) loops[side].push_back(h);
    }
  }
  std::vector<Loop2> gridded[2] = {loops[0], loops[1]};
  snap_round_on_grid(gridded);
  EXPECT_TRUE(noded(gridded));
  SnapRoundingStats stats;
  snap_round(loops, &stats);
  EXPECT_TRUE(stats.on_grid);
  EXPECT_EQ(loops[0], gridded[0]);
  EXPECT_EQ(loops[1], gridded[1]);

  std::vector<Loop2> ordinary[2] = {{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}},
                                    {{{2, 2}, {6, 2}, {6, 6}, {2, 6}}}};
  snap_round(ordinary, &stats, SnapPath::kRoundsOnly);
  EXPECT_FALSE(stats.on_grid);
}

// The area bound of the grid: every vertex moves less than 12u·M and every edge's route
// stays within that of it (its points are centres of cells it meets), so an area moves
// by less than that times the boundaries' length, twice over for second-order terms.
double grid_area_bound(const PolygonSet2& subject, const PolygonSet2& clip) {
  double magnitude = 0.0, perimeter = 0.0;
  for (const PolygonSet2* set : {&subject, &clip}) {
    for (const PolygonWithHoles2& p : *set) {
      std::vector<const Loop2*> loops = {&p.outer};
      for (const Loop2& h : p.holes) loops.push_back(&h);
      for (const Loop2* loop : loops) {
        for (std::size_t i = 0; i < loop->size(); ++i) {
          const Point2& a = (*loop)[i];
          const Point2& b = (*loop)[(i + 1) % loop->size()];
          magnitude = std::max({magnitude, std::fabs(a.x), std::fabs(a.y)});
          perimeter += std::hypot(b.x - a.x, b.y - a.y);
        }
      }
    }
  }
  return 2.0 * 12.0 * 0x1p-53 * magnitude * perimeter;
}

// Clips whose snapping all goes to the grid (the rounds stopped at once), held against
// CGAL's exact answer: random polygons with holes, polygons on a coarse grid (shared
// edges, vertices on edges, collinear overlaps) and stars of almost concurrent lines. Each
// grid result is noded, or the clip would throw.
TEST(GridSnap, ClipsThroughTheGridAloneMatchTheExactOverlay) {
  const SnapRoundLimitForTesting grid_only(0, 0, true);
  std::mt19937_64 rng(7);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    PolygonSet2 subject, clip;
    if (trial % 3 == 0) {
      subject = {test::random_polygon_with_holes(rng)};
      clip = {test::random_polygon_with_holes(rng)};
    } else if (trial % 3 == 1) {
      subject = {test::random_grid_polygon(rng)};
      clip = {test::random_grid_polygon(rng)};
    } else {
      for (PolygonSet2* side : {&subject, &clip}) {
        *side = normalized(PolygonSet2{{test::almost_concurrent_star(rng, 3 + trial % 5), {}}});
      }
    }
    if (test::input_problem(subject) != "" || test::input_problem(clip) != "") continue;
    const test::ClipCheck check = test::check_clip(subject, clip, {.swapped = true});
    const double bound = std::max(grid_area_bound(subject, clip),
                                  1e-12 * std::max(check.exact.subject, check.exact.clip));
    EXPECT_EQ(check.failure(bound, bound), "") << trial << "\n"
                                               << test::describe(check, subject, clip);
    ++checked;
  }
  EXPECT_GE(checked, 200);
}

}  // namespace
}  // namespace shadowgen::clipper::detail
