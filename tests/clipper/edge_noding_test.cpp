// The noding step between tracing and assembly (clipper/detail/edge_noding.h) and the
// order of points along a segment it shares with the insertion of crossings.

#include "clipper/detail/edge_noding.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "clipper/detail/crossing.h"

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

}  // namespace
}  // namespace shadowgen::clipper::detail
