// The noding step between tracing and assembly (clipper/detail/edge_noding.h), the
// order of points along a segment it shares with the insertion of crossings, and the
// merging of crossings into vertices an ulp away (clipper/detail/vertex_merge.h).

#include "clipper/detail/edge_noding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "clipper/detail/crossing.h"
#include "clipper/detail/vertex_merge.h"

namespace shadowgen::clipper::detail {
namespace {

using Points = std::unordered_set<Point2, Point2Hash>;

bool has_edge(const std::vector<DirectedEdge>& edges, const Point2& from, const Point2& to) {
  return std::any_of(edges.begin(), edges.end(),
                     [&](const DirectedEdge& e) { return e.from == from && e.to == to; });
}

TEST(EdgeNoding, CrossingEdgesTouchingAConstructedPointAreSplitWhereTheyCross) {
  const Point2 c{1, 1};  // a constructed point: the edge leaving it may have moved
  const std::vector<DirectedEdge> edges{{c, {3, 3}}, {{3, 1}, {1, 3}}};
  NodingStats stats;
  const auto out = node_edges(edges, Points{c}, &stats);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(stats.rounds, 1);
  EXPECT_TRUE(has_edge(out, c, {2, 2}));
  EXPECT_TRUE(has_edge(out, {2, 2}, {3, 3}));
  EXPECT_TRUE(has_edge(out, {3, 1}, {2, 2}));
  EXPECT_TRUE(has_edge(out, {2, 2}, {1, 3}));
}

TEST(EdgeNoding, EdgesAwayFromConstructedPointsAreNotTested) {
  // Exact pieces of input edges were noded when the crossings were found; a crossing
  // between two of them here would be a contract violation upstream, not repaired.
  const std::vector<DirectedEdge> edges{{{1, 1}, {3, 3}}, {{3, 1}, {1, 3}}};
  const auto out = node_edges(edges, Points{{10, 10}});
  EXPECT_EQ(out.size(), 2u);
}

TEST(EdgeNoding, AVertexOnAnotherEdgeSplitsItExactly) {
  const Point2 c{0, 0};
  const std::vector<DirectedEdge> edges{{c, {4, 0}}, {{2, 0}, {2, 2}}, {{1, -1}, {2, 0}}};
  const auto out = node_edges(edges, Points{c});
  EXPECT_TRUE(has_edge(out, c, {2, 0}));
  EXPECT_TRUE(has_edge(out, {2, 0}, {4, 0}));
  EXPECT_EQ(out.size(), 4u);
}

TEST(EdgeNoding, EdgesRunningBothWaysAlongASegmentCancel) {
  // A fold: a -> b -> a' with a' on a -> b. After the split the stretch a' <-> b is
  // traversed both ways and bounds nothing.
  const Point2 a{0, 0}, b{4, 0}, fold{2, 0};
  const std::vector<DirectedEdge> edges{{a, b}, {b, fold}, {fold, {2, 3}}};
  NodingStats stats;
  const auto out = node_edges(edges, Points{b}, &stats);
  EXPECT_EQ(stats.cancelled, 2u);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(has_edge(out, a, fold));
  EXPECT_TRUE(has_edge(out, fold, {2, 3}));
}

TEST(AlongSegment, TiesInTheMainCoordinateGoByTheOtherInTheSegmentsDirection) {
  // A 45-degree segment: x is the main coordinate; two rounded crossings share x.
  const Point2 p{0, 0}, q{3, 3};
  const Point2 lower{2, 1.9999999999999996}, upper{2, 2};
  EXPECT_TRUE(AlongSegment(p, q)(lower, upper));
  EXPECT_FALSE(AlongSegment(p, q)(upper, lower));
  EXPECT_TRUE(AlongSegment(q, p)(upper, lower));
  // Descending in x but ascending in y.
  EXPECT_TRUE(AlongSegment({3, 0}, {0, 3})({2, 1}, {2, 1.5}));
}

TEST(CrossingPoint, DoesNotDependOnTheOrderOfTheSegmentsOrOfTheirEnds) {
  const Point2 a0{0.1, 0.3}, a1{7.7, 2.9}, b0{3.3, -1.1}, b1{2.2, 9.7};
  const Point2 p = crossing_point(a0, a1, b0, b1);
  EXPECT_EQ(p, crossing_point(b0, b1, a0, a1));
  EXPECT_EQ(p, crossing_point(a1, a0, b1, b0));
}

// Vertex–vertex snapping (clipper/detail/vertex_merge.h).

Point2 ulps_right(Point2 p, int n) {
  for (int i = 0; i < n; ++i) p.x = std::nextafter(p.x, INFINITY);
  return p;
}

// The needle of the regression case scaled-1e-4-hole-collapsed-to-a-sliver: out to b
// from the input vertex v, back to a crossing c an ulp beside v.
const Point2 kV{6.7759635681812032e-07, 7.869756666827503e-05};
const Point2 kB{7.8935476479682582e-06, 7.4679836327726617e-05};

TEST(VertexMerge, ACrossingAnUlpFromAnInputVertexBecomesThatVertexAndTheNeedleCancels) {
  const Point2 c = ulps_right(kV, 1);
  const std::vector<DirectedEdge> edges{{kV, kB}, {kB, c}, {c, kV}};
  Points moved;
  const auto merged = merge_close_vertices(
      edges, Points{c}, [](const Point2& p) { return p == kV; }, moved);
  ASSERT_EQ(merged.size(), 2u);  // c -> v shrank to a point
  EXPECT_TRUE(has_edge(merged, kV, kB));
  EXPECT_TRUE(has_edge(merged, kB, kV));
  EXPECT_EQ(moved, Points{kV});
  EXPECT_TRUE(node_edges(merged, moved).empty());  // one segment run both ways
}

TEST(VertexMerge, InputVerticesNeverMove) {
  const Point2 w = ulps_right(kV, 1);
  const std::vector<DirectedEdge> edges{{kV, kB}, {kB, w}, {w, kV}};
  Points moved;
  const auto merged = merge_close_vertices(
      edges, Points{w}, [](const Point2&) { return true; }, moved);
  EXPECT_EQ(merged.size(), 3u);
  EXPECT_TRUE(moved.empty());
}

TEST(VertexMerge, CloseCrossingsMergeIntoTheLeastWhateverTheEdgeOrder) {
  const Point2 c1 = ulps_right(kV, 1), c2 = ulps_right(kV, 2);
  std::vector<DirectedEdge> edges{{kB, c2}, {c1, {0, 0}}, {{0, 0}, kB}, {c2, c1}};
  for (int turn = 0; turn < 4; ++turn) {
    std::rotate(edges.begin(), edges.begin() + 1, edges.end());
    Points moved;
    const auto merged = merge_close_vertices(
        edges, Points{c1, c2, kB, {0, 0}}, [](const Point2&) { return false; }, moved);
    ASSERT_EQ(merged.size(), 3u);
    EXPECT_TRUE(has_edge(merged, kB, c1));
    EXPECT_TRUE(has_edge(merged, c1, {0, 0}));
    EXPECT_EQ(moved, Points{c1});
  }
}

TEST(VertexMerge, CrossingsNearerThanTheirErrorBoundsMerge) {
  // 2 ulps apart in y near 0.15: beyond 2u·|P| (3.3e-17), within two error radii of 4e-16.
  const Point2 d{-0.15000000000000002, -0.15000000000000002};
  const Point2 e{-0.15000000000000002, -0.14999999999999997};
  const Point2 far{-0.18, -0.12};
  const std::vector<DirectedEdge> edges{{far, d}, {e, far}, {d, e}};
  Points moved;
  const auto kept = merge_close_vertices(
      edges, Points{d, e}, [](const Point2&) { return false; }, moved);
  EXPECT_EQ(kept.size(), 3u);  // by distance alone they stay apart
  const ErrorRadii radii{{d, 4e-16}, {e, 4e-16}};
  const auto merged = merge_close_vertices(
      edges, Points{d, e}, [](const Point2&) { return false; }, moved, &radii);
  ASSERT_EQ(merged.size(), 2u);  // d -> e shrank to a point
  EXPECT_TRUE(has_edge(merged, far, d));
  EXPECT_TRUE(has_edge(merged, d, far));
  const ErrorRadii tight{{d, 2e-17}, {e, 2e-17}};
  EXPECT_EQ(merge_close_vertices(
                edges, Points{d, e}, [](const Point2&) { return false; }, moved, &tight)
                .size(),
            3u);
}

TEST(VertexMerge, PointsFartherThanTheSnapDistanceStay) {
  // 2u·|P| is about 1.7e-20 here; 64 ulps of x (1e-22 each) is well inside, 1e6 ulps not.
  const Point2 near = ulps_right(kV, 64), far = ulps_right(kV, 1000000);
  Points moved;
  auto merged = merge_close_vertices(
      {{kV, kB}, {kB, near}}, Points{near}, [](const Point2& p) { return p == kV; }, moved);
  EXPECT_TRUE(has_edge(merged, kB, kV));
  moved.clear();
  merged = merge_close_vertices(
      {{kV, kB}, {kB, far}}, Points{far}, [](const Point2& p) { return p == kV; }, moved);
  EXPECT_TRUE(has_edge(merged, kB, far));
  EXPECT_TRUE(moved.empty());
}

}  // namespace
}  // namespace shadowgen::clipper::detail

namespace shadowgen::clipper::detail {
namespace {

// The fuzzer's case (tests/clipper/regressions/crossings-rounded-out-of-order.wkt): an
// edge passing 1.2e-15 above a vertex crosses both edges there, 1e-16 apart; rounded,
// the two crossings compare the wrong way round, exactly they do not.
TEST(ExactlyAlongSegment, OrdersCrossingsLessThanARoundingApartExactly) {
  const Point2 e0{-7.9999999999999432, -7.9999999999999964}, e1{1.0, -8.0};
  const Point2 vertex{-2.0, -8.0}, before{-4.0009727478027344, -2.0000000000000036};
  const Point2 after{-3.9999999999999574, 0.0};
  const EdgePoint first{crossing_point(e0, e1, before, vertex), true, before, vertex};
  const EdgePoint second{crossing_point(e0, e1, vertex, after), true, vertex, after};
  ASSERT_TRUE(AlongSegment(e0, e1)(second.point, first.point));  // rounding's order
  const ExactlyAlongSegment along(e0, e1);
  EXPECT_TRUE(along(first, second));
  EXPECT_FALSE(along(second, first));
  EXPECT_FALSE(along(first, first));
  // A vertex exactly on the edge is ordered against crossings exactly too.
  const EdgePoint end{e1};
  EXPECT_TRUE(along(second, end));
  EXPECT_FALSE(along(end, first));
}

}  // namespace
}  // namespace shadowgen::clipper::detail
