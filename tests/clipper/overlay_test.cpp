// The winding-number overlay (clipper/detail/overlay.h) on hand-made noded loops: the
// inside and outside edges it gives, traced into polygons, bound exactly the regions the
// operands' winding numbers say, whatever the multiplicities and however the graph
// falls apart into parts.

#include "clipper/detail/overlay.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "clipper/detail/boundary_graph.h"
#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {
namespace {

Loop2 square(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Loop2 reversed(Loop2 loop) {
  std::reverse(loop.begin(), loop.end());
  return loop;
}

struct Pieces {
  PolygonSet2 inside, outside;
};

Pieces combine(const std::vector<Loop2>& subject, const std::vector<Loop2>& clip) {
  const std::vector<Loop2> loops[2] = {subject, clip};
  const OverlayEdges edges = overlay(loops);
  return {assemble_polygons(edges.inside, edges.point_count),
          assemble_polygons(edges.outside, edges.point_count)};
}

TEST(Overlay, OverlappingSquaresSharingAVertexRow) {
  // Noded, as the overlay needs: each has the other's vertices along the shared stretch.
  const Loop2 subject{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {2, 4}, {0, 4}};
  const Loop2 clip{{2, 0}, {4, 0}, {6, 0}, {6, 4}, {4, 4}, {2, 4}};
  const Pieces p = combine({subject}, {clip});
  EXPECT_EQ(area(p.inside), 8.0);
  EXPECT_EQ(area(p.outside), 8.0);
  ASSERT_EQ(p.inside.size(), 1u);
  ASSERT_EQ(p.outside.size(), 1u);
}

TEST(Overlay, ALoopRunTwiceCountsOnce) {
  // Winding number 2 inside: still inside, and no edge is doubled in the output.
  const Loop2 s{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {2, 4}, {0, 4}};
  const Pieces p = combine({s, s}, {Loop2{{2, 0}, {4, 0}, {4, 4}, {2, 4}}});
  EXPECT_EQ(area(p.inside), 8.0);
  EXPECT_EQ(area(p.outside), 8.0);
  ASSERT_EQ(p.outside.size(), 1u);
  EXPECT_EQ(p.outside[0].outer.size(), 4u);
}

TEST(Overlay, ANeedleRunBothWaysBoundsNothing) {
  // The subject's loop runs out to (8, 2) and straight back: the two cancel.
  const Loop2 subject{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {8, 2}, {4, 2}, {4, 4}, {2, 4}, {0, 4}};
  const Loop2 clip{{2, 0}, {4, 0}, {9, 0}, {9, 4}, {4, 4}, {2, 4}};
  const Pieces p = combine({subject}, {clip});
  EXPECT_EQ(area(p.inside), 8.0);
  EXPECT_EQ(area(p.outside), 8.0);
  for (const PolygonWithHoles2& q : p.inside) {
    EXPECT_EQ(std::count(q.outer.begin(), q.outer.end(), Point2{8, 2}), 0);
  }
}

TEST(Overlay, PartsNestedInHolesAreLocatedExactly) {
  // Nothing shares a vertex: the subject's ring, an island of the clip inside its hole,
  // an island of the subject inside that island's hole, and a clip square around all.
  const std::vector<Loop2> subject{square(0, 0, 10, 10), reversed(square(2, 2, 8, 8)),
                                   square(4.5, 4.5, 5.5, 5.5)};
  const std::vector<Loop2> clip{square(3, 3, 7, 7), reversed(square(4, 4, 6, 6))};
  const Pieces p = combine(subject, clip);
  EXPECT_EQ(area(p.inside), 0.0);  // the clip ring lies in the subject's hole
  EXPECT_EQ(area(p.outside), 100.0 - 36.0 + 1.0);
  const Pieces around = combine(subject, {square(-1, -1, 11, 11)});
  EXPECT_EQ(area(around.inside), 100.0 - 36.0 + 1.0);
  EXPECT_TRUE(around.outside.empty());
  ASSERT_EQ(around.inside.size(), 2u);  // the ring with its hole, and the island
}

TEST(Overlay, ALoopTurnedClockwiseBoundsNoRegion) {
  // A clockwise loop alone has winding number −1 inside: not in the operand's region.
  const Pieces p = combine({reversed(square(0, 0, 4, 4))}, {square(1, 1, 3, 3)});
  EXPECT_TRUE(p.inside.empty());
  EXPECT_TRUE(p.outside.empty());
}

TEST(Overlay, IdenticalOperandsAreAllInside) {
  const Loop2 s{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  const Pieces p = combine({s}, {s});
  EXPECT_EQ(area(p.inside), 5.0);
  EXPECT_TRUE(p.outside.empty());
  const Pieces opposite = combine({s}, {reversed(s)});
  EXPECT_TRUE(opposite.inside.empty());
  EXPECT_EQ(area(opposite.outside), 5.0);
}

}  // namespace
}  // namespace shadowgen::clipper::detail
