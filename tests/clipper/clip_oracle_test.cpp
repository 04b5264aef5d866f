// clip() against CGAL's exact answer: 10,000 seeded random pairs of concave polygons
// with holes (half in generic double coordinates, half on a coarse integer grid where
// shared vertices and collinear overlapping edges are the rule), then hand-made
// degenerate pairs.
//
// Every case is run in both argument orders and checked for: inside and outside areas
// equal to the exact intersection and difference, inside + outside = subject, the same
// intersection area both ways, every output polygon valid (validity_problem: what CGAL's
// is_valid_polygon_with_holes accepts, with simple loops as clip.h promises).
//
// Tolerance: 1e-12 × the subject's area (the clip's, for the swapped run). The clipper
// rounds only intersection points, each by about u·|P| (u = 2^-53, clip.h); with
// coordinates and perimeters of order 1 and areas of order 1 here, the area error is a
// few u per constructed vertex, below 1e-14 of the area, so 1e-12 leaves room for some
// hundred intersection points and still catches any lost or extra piece.

#include <gtest/gtest.h>

#include <algorithm>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>

#include "clipper/clip.h"
#include "tests/support/cgal_oracle.h"
#include "tests/support/clip_check.h"
#include "tests/support/expect.h"
#include "tests/support/random_polygons.h"

namespace shadowgen::test {
namespace {

using clipper::Loop2;
using clipper::Point2;

constexpr double kRelativeTolerance = 1e-12;

// 10 shards of 1,000 pairs: 5 of generic doubles, 5 on the grid. Each shard is one CTest
// test, so they run in parallel.
constexpr int kShards = 5;
constexpr int kPairsPerShard = 1000;

using Generator = std::function<PolygonWithHoles2(std::mt19937_64&)>;

// Each case draws from its own generator seeded by (suite seed, case index), so a
// failing case is reproduced by its index alone.
std::mt19937_64 case_rng(std::uint64_t suite_seed, int index) {
  std::seed_seq seq{suite_seed, static_cast<std::uint64_t>(index)};
  return std::mt19937_64(seq);
}

struct ShardStats {
  int pairs = 0;
  int empty_inside = 0;
  int empty_outside = 0;
  int outputs_with_holes = 0;
  double worst_relative_error = 0.0;
};

void RunRandomShard(const std::string& suite, std::uint64_t seed, int shard,
                    const Generator& generate) {
  CaseFailures failures(suite);
  ShardStats stats;
  for (int i = shard * kPairsPerShard; i < (shard + 1) * kPairsPerShard; ++i) {
    std::mt19937_64 rng = case_rng(seed, i);
    const PolygonSet2 subject{generate(rng)};
    const PolygonSet2 clip{generate(rng)};
    const ClipCheck check = check_clip(subject, clip);
    failures.record("case-" + std::to_string(i),
                    check.failure(kRelativeTolerance * check.exact.subject,
                                  kRelativeTolerance * check.exact.clip),
                    check, subject, clip);
    ++stats.pairs;
    stats.empty_inside += check.forward.inside.empty() ? 1 : 0;
    stats.empty_outside += check.forward.outside.empty() ? 1 : 0;
    for (const PolygonWithHoles2& p : check.forward.inside) {
      stats.outputs_with_holes += p.holes.empty() ? 0 : 1;
    }
    for (const PolygonWithHoles2& p : check.forward.outside) {
      stats.outputs_with_holes += p.holes.empty() ? 0 : 1;
    }
    stats.worst_relative_error =
        std::max({stats.worst_relative_error, check.forward_error() / check.exact.subject,
                  std::max({check.swapped_inside_error, check.swapped_outside_error,
                            check.swapped_conservation_error}) /
                      check.exact.clip,
                  check.swap_mismatch / check.exact.subject});
  }
  std::printf(
      "%s shard %d: %d pairs, %d pass, %d fail; empty inside %d, empty outside %d, output "
      "polygons with holes %d; worst relative area error %.3g (tolerance %.0e)\n",
      suite.c_str(), shard, stats.pairs, stats.pairs - failures.count(), failures.count(),
      stats.empty_inside, stats.empty_outside, stats.outputs_with_holes, stats.worst_relative_error,
      kRelativeTolerance);
  if (failures.count() > 0) std::printf("  failures: %s\n", failures.summary().c_str());
  EXPECT_EQ(failures.count(), 0) << "of " << stats.pairs << " pairs";
}

class RandomDoublePairs : public ::testing::TestWithParam<int> {};

TEST_P(RandomDoublePairs, MatchExactOverlay) {
  RunRandomShard("random-doubles", 0x5eed0001, GetParam(), random_polygon_with_holes);
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomDoublePairs, ::testing::Range(0, kShards));

class RandomGridPairs : public ::testing::TestWithParam<int> {};

TEST_P(RandomGridPairs, MatchExactOverlay) {
  RunRandomShard("random-grid", 0x5eed0002, GetParam(), random_grid_polygon);
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomGridPairs, ::testing::Range(0, kShards));

// --- hand-made degenerate pairs -----------------------------------------------------------

Loop2 square(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Loop2 reversed(Loop2 loop) {
  std::reverse(loop.begin(), loop.end());
  return loop;
}

int hole_count(const PolygonSet2& polygons) {
  int holes = 0;
  for (const PolygonWithHoles2& p : polygons) holes += static_cast<int>(p.holes.size());
  return holes;
}

void ExpectBothWays(const std::string& name, const PolygonSet2& a, const PolygonSet2& b) {
  ExpectClipMatchesOracle(name, a, b, kRelativeTolerance);
}

TEST(DegeneratePairs, IdenticalPolygons) {
  std::mt19937_64 rng(11);
  for (int i = 0; i < 50; ++i) {
    PolygonWithHoles2 p = i % 2 == 0 ? random_polygon_with_holes(rng) : random_grid_polygon(rng);
    const PolygonSet2 subject{p};
    randomize_loops(p, rng);  // same region, other orientation and starting vertices
    const PolygonSet2 clip{p};
    SCOPED_TRACE("identical pair " + std::to_string(i));
    ExpectBothWays("identical-" + std::to_string(i), subject, clip);
    const clipper::ClipResult result = clipper::clip(subject, clip);
    EXPECT_TRUE(result.outside.empty());
    ASSERT_EQ(result.inside.size(), 1u);
    EXPECT_EQ(result.inside[0].holes.size(), p.holes.size());
  }
}

TEST(DegeneratePairs, OneInsideTheOtherMakesAHole) {
  const PolygonSet2 big{{square(0, 0, 10, 10), {}}};
  const PolygonSet2 small{{{{3, 3}, {6, 2.5}, {5, 5}, {7, 7}, {2, 6}}, {}}};
  ExpectBothWays("small-inside-big", big, small);
  const clipper::ClipResult result = clipper::clip(big, small);
  ASSERT_EQ(result.outside.size(), 1u);
  EXPECT_EQ(result.outside[0].holes.size(), 1u) << "the small polygon becomes a hole";
  EXPECT_EQ(hole_count(result.inside), 0);

  // Inside a polygon with holes, beside its holes: the outside gets one more hole.
  std::mt19937_64 rng(5);
  int placed = 0;
  for (int i = 0; i < 30; ++i) {
    const PolygonWithHoles2 p = random_polygon_with_holes(rng);
    const double scale = 1e-3;
    const Point2 anchor = p.outer[0];
    // A tiny triangle just inside the outer loop near vertex 0, towards the centroid of
    // the next two vertices: inside the area, far from the holes.
    const Point2 toward{(p.outer[1].x + p.outer[2].x) / 2 - anchor.x,
                        (p.outer[1].y + p.outer[2].y) / 2 - anchor.y};
    const Point2 c{anchor.x + 0.05 * toward.x, anchor.y + 0.05 * toward.y};
    const PolygonSet2 tiny{{{{c.x, c.y}, {c.x + scale, c.y}, {c.x, c.y + scale}}, {}}};
    if (!input_problem(tiny).empty()) continue;
    const ExactAreas exact = exact_clip_areas({p}, tiny);
    if (exact.inside != exact.clip) continue;  // not wholly inside after all
    ++placed;
    ExpectBothWays("tiny-inside-" + std::to_string(i), {p}, tiny);
    const clipper::ClipResult r = clipper::clip(PolygonSet2{p}, tiny);
    EXPECT_EQ(hole_count(r.outside), static_cast<int>(p.holes.size()) + 1);
  }
  EXPECT_GE(placed, 10) << "too few tiny triangles fell wholly inside";
}

TEST(DegeneratePairs, TouchingAtAVertex) {
  const PolygonSet2 a{{square(0, 0, 2, 2), {}}};
  ExpectBothWays("corner-to-corner", a, {{square(2, 2, 4, 4), {}}});
  ExpectBothWays("vertex-on-edge", a, {{{{2, 1}, {4, 0}, {4, 3}}, {}}});
  ExpectBothWays("vertex-into-notch", {{{{0, 0}, {4, 0}, {2, 2}, {4, 4}, {0, 4}}, {}}},
                 {{{{2, 2}, {5, 1}, {5, 3}}, {}}});
  const clipper::ClipResult r = clipper::clip(a, PolygonSet2{{square(2, 2, 4, 4), {}}});
  EXPECT_TRUE(r.inside.empty()) << "a touch has no area";
  ASSERT_EQ(r.outside.size(), 1u);
}

TEST(DegeneratePairs, SharingAnEdge) {
  const PolygonSet2 a{{square(0, 0, 2, 2), {}}};
  ExpectBothWays("whole-edge", a, {{square(2, 0, 4, 2), {}}});
  ExpectBothWays("part-of-edge", a, {{square(2, 1, 4, 3), {}}});
  ExpectBothWays("edge-inside-edge", a, {{square(2, 0.5, 3, 1.5), {}}});
  ExpectBothWays("overlapping-along-edge", a, {{square(1, 0, 3, 2), {}}});
  ExpectBothWays("inner-edge-on-edge", a, {{square(0.5, 0, 1.5, 1), {}}});
  ExpectBothWays("reversed-orientation", a, {{reversed(square(2, 0, 4, 2)), {}}});
  const clipper::ClipResult r = clipper::clip(a, PolygonSet2{{square(2, 0, 4, 2), {}}});
  EXPECT_TRUE(r.inside.empty()) << "a shared edge has no area";
}

TEST(DegeneratePairs, HolesTouchingTheOuterLoopAtAPoint) {
  // The hole's vertex (2, 0) is a vertex of the outer loop.
  const PolygonSet2 notched{{{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{2, 0}, {1, 2}, {3, 2}}}}};
  ASSERT_EQ(validity_problem(notched), "");
  ExpectBothWays("cover-all", notched, {{square(-1, -1, 5, 5), {}}});
  ExpectBothWays("cut-through-touch", notched, {{square(1.5, -1, 2.5, 5), {}}});
  ExpectBothWays("left-half", notched, {{square(-1, -1, 2, 5), {}}});
  ExpectBothWays("the-hole-itself", notched, {{{{2, 0}, {3, 2}, {1, 2}}, {}}});
  ExpectBothWays("touching-the-touch", notched, {{{{2, 0}, {3, -1}, {1, -1}}, {}}});
  ExpectBothWays("bottom-strip", notched, {{square(-1, -1, 5, 1), {}}});
  const clipper::ClipResult r = clipper::clip(notched, PolygonSet2{{{{2, 0}, {3, 2}, {1, 2}}, {}}});
  EXPECT_TRUE(r.inside.empty()) << "the clip is exactly the hole";

  // Two holes touching each other at (3 1) and the outer loop at (0 2) and (6 2).
  const PolygonSet2 two{{{{0, 0}, {6, 0}, {6, 2}, {6, 4}, {0, 4}, {0, 2}},
                         {{{0, 2}, {3, 3}, {3, 1}}, {{{3, 1}, {4.5, 3}, {6, 2}}}}}};
  ASSERT_EQ(input_problem(two), "");
  ExpectBothWays("two-holes-chain", two, {{square(1, 0.5, 5, 3.5), {}}});
  ExpectBothWays("two-holes-diamond", two, {{{{3, -1}, {7, 2}, {3, 5}, {-1, 2}}, {}}});
}

TEST(DegeneratePairs, ClipFillsASubjectHole) {
  const PolygonSet2 frame{{square(0, 0, 6, 6), {reversed(square(2, 2, 4, 4))}}};
  ExpectBothWays("fills-hole", frame, {{square(2, 2, 4, 4), {}}});
  ExpectBothWays("hole-and-more", frame, {{square(1, 1, 5, 5), {}}});
  ExpectBothWays("same-frame", frame, frame);
  ExpectBothWays("outer-only", frame, {{square(0, 0, 6, 6), {}}});
  ExpectBothWays("hole-edge-shared", frame, {{square(2, 2, 3, 4), {}}});
  const clipper::ClipResult r = clipper::clip(frame, PolygonSet2{{square(2, 2, 4, 4), {}}});
  EXPECT_TRUE(r.inside.empty());
  ExpectAreaNear(r.outside, 32.0, 0.0);
}

TEST(DegeneratePairs, Multipolygons) {
  const PolygonSet2 two{{square(0, 0, 2, 2), {}}, {square(3, 0, 5, 2), {}}};
  ExpectBothWays("bridge", two, {{square(1, 0.5, 4, 1.5), {}}});
  ExpectBothWays("corner-touching-parts", {{square(0, 0, 2, 2), {}}, {square(2, 2, 4, 4), {}}},
                 {{{{2, 0}, {4, 2}, {2, 4}, {0, 2}}, {}}});
  ExpectBothWays("island-in-hole",
                 {{square(0, 0, 6, 6), {reversed(square(1, 1, 5, 5))}}, {square(2, 2, 4, 4), {}}},
                 {{square(3, -1, 7, 7), {}}});
}

}  // namespace
}  // namespace shadowgen::test
