#pragma once

// The Weiler–Atherton clipper (Weiler and Atherton 1977; Atherton, Weiler and Greenberg
// 1978, section III): a concave subject with holes against a concave clip with holes,
// giving both the inside pieces (subject ∩ clip) and the outside pieces (subject − clip).
//
// Method. The two boundaries are first snap rounded together (detail/snap_rounding.h):
// every crossing and touching point is inserted into both, as a double, and the step is
// repeated until the edges meet only at common vertices or as the very same segment.
// Every later decision is then an exact predicate on that plane graph, with no rounded
// point left to disagree with it. Each face of the graph has a winding number for each
// operand; crossing an edge changes them by the operands' net multiplicities along it,
// so they spread exactly from edge to edge around each vertex (detail/overlay.h): the
// entry/exit alternation of the paper, at a touch as at a crossing, and for a boundary
// that snapping ran along one segment twice or folded onto itself. An edge bounds the
// inside pieces where the faces on one side lie in both regions and those on the other
// do not (the outside pieces likewise); the pieces are then traced. Where several
// traced edges meet at one point, the walk keeps to the tightest turn, and the loops are
// split at repeated vertices, so every output loop is simple.
//
// Input. Any PolygonWithHoles2 / PolygonSet2 whose region is well formed: loops simple,
// holes inside their outer loop, loops meeting at most at points. Orientation is free
// (normalized on entry, by each loop's body: see encloses_counter_clockwise in
// normalize.h). Repeated vertices, zero-area spikes and collinear vertices are
// removed first; loops left with no area are dropped. Self-crossing loops are outside
// the contract (the result is then unspecified, but the call returns, and its loops are
// still simple: the snapping nodes them too), with one exception that rounding makes
// common: a loop that crosses itself only within rounding of its vertices counts as its
// body, and the slivers it closes off count as their windings say.
//
// Output. Polygons in the conventions of clipper/polygon.h: outer loops counter-
// clockwise, holes clockwise and attached to the smallest outer loop that contains
// them, no repeated vertices, no zero-length edges, no spikes. Vertices where a loop runs
// straight on are kept: one may be where another loop touches it.
//
// Touching loops of one operand (a hole touching its outer loop, polygons of a set
// meeting at a point) are noded by the same snapping. Where the snapping has run one
// operand's boundary both ways along a segment (a needle of its region, or a crack,
// narrower than the resolution below), the two copies cancel: they bound nothing.
//
// Exactness and tolerance. Orientation and side tests are exact (predicates.h). New
// points are the crossings, each coordinate within 5u of its own magnitude of the exact
// crossing (u = 2^-53; detail/crossing.h), however long the edges and whatever the
// angle. The one tolerance is the hot pixel of a point (detail/snap.h): the square of six
// ulps of its largest coordinate's magnitude around it, derived from that bound. An edge passing
// through a vertex's pixel is routed through the vertex; vertices in each other's pixels
// become one; both move the boundary by at most a pixel there. The tolerance is relative
// to the coordinates' magnitude where the point lies, not to the edge lengths or to
// coordinates elsewhere: a feature of 1e-9 near the origin is kept beside coordinates of
// 1e8.
//
// Limit. Where a feature is narrower than the pixels around it (a needle a few ulps
// wide), the snapping closes it up or folds it onto its neighbours; the winding numbers
// count such folds as they are, so the pieces are the Boolean combination of the snapped
// operands, which differ from the input by the pixels that moved them. The snapping is
// iterated, and nothing proves that it always ends with edges meeting only at vertices:
// it can cycle, cutting sliver loops out of routes and putting their points back. The
// rounds first keep such points out, then, where that leaves edges crossing, run again
// putting them back, stopping after 17 rounds of changes at the first state whose edges
// are checked exactly to meet only at vertices, within 34 rounds more. Where neither
// way ends noded, the operands are snap rounded on a grid instead (detail/grid_snap.h),
// which nodes them by construction and moves each vertex of the loops snapped together
// by less than 12u·M, M their largest coordinate magnitude: the pixel at M, however
// small the vertex's own magnitude. The result is checked exactly all the same; were it
// not noded, the pieces would still be valid loops but their areas could be wrong by
// more than the grid accounts for, so the call would throw SnapRoundingError instead
// of returning them.
//
// Cost. Candidate edge pairs come from a sweep over x with y-interval rejection, so a
// clip costs O((n + k) log n + m) for n edges, k intersections and m pairs of edges
// whose x-ranges overlap, instead of the all-pairs O(n²).

#include <cstddef>
#include <span>
#include <stdexcept>

#include "clipper/box.h"
#include "clipper/polygon.h"

namespace shadowgen::clipper {

// The snapping ended with edges still meeting elsewhere than at common vertices, after
// the rounds and the grid both (see Limit above): thrown by clip(), intersection(),
// difference() and merge_adjacent() (merge.h) in place of pieces whose areas could be
// wrong. The clipper does not know what its operands stand for; a caller that does names
// it and passes the failure on.
class SnapRoundingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs `work` on behalf of item `index` of the caller's (a polygon, a face part) and
// returns its result; a clip in it whose snapping does not settle comes out as
// Error(index, message), so the caller's caller learns which item failed.
template <class Error, class Work>
auto failing_as(std::size_t index, Work&& work) {
  try {
    return work();
  } catch (const SnapRoundingError& e) {
    throw Error(index, e.what());
  }
}

// For tests of that failure, which no known input causes, and of the grid: while one
// lives, the snapping stops after `rounds` rounds of changes instead of 17, and looks
// `search` rounds more instead of 34 for edges meeting only at vertices (with 0 and 0 it
// changes nothing), and, unless `on_grid`, it does not snap on a grid where the rounds
// end with edges crossing: then operands whose edges cross or end inside one another
// fail. Process-wide; the previous bounds come back when it ends.
class SnapRoundLimitForTesting {
 public:
  explicit SnapRoundLimitForTesting(int rounds, int search = 0, bool on_grid = false);
  ~SnapRoundLimitForTesting();
  SnapRoundLimitForTesting(const SnapRoundLimitForTesting&) = delete;
  SnapRoundLimitForTesting& operator=(const SnapRoundLimitForTesting&) = delete;

 private:
  int previous_;
  int previous_search_;
  bool previous_on_grid_;
};

struct ClipResult {
  PolygonSet2 inside;   // subject ∩ clip
  PolygonSet2 outside;  // subject − clip
};

ClipResult clip(const PolygonSet2& subject, const PolygonSet2& clip_region);
ClipResult clip(const PolygonWithHoles2& subject, const PolygonWithHoles2& clip_region);

// One subject against several clip polygons, as hidden-surface removal needs: inside is
// subject ∩ (union of the clips), outside is subject − (union of the clips). The clips
// may overlap each other. They are one operand of a single snap rounding and overlay:
// their winding numbers add up, and the union is where the sum is positive. So every
// piece comes from the same snapped graph, and pieces that share a boundary share its
// vertices and do not overlap. Clips whose boxes miss the subject's are left out.
ClipResult clip(const PolygonWithHoles2& subject, std::span<const PolygonWithHoles2> clips);

// A clip region that many subjects are clipped by, as a template of hidden-surface
// removal clips every piece behind it: normalized and taken apart into loops once.
// clip(subject) is clip(subject, clip_region), the same pieces bit for bit.
class ClipRegion {
 public:
  explicit ClipRegion(const PolygonWithHoles2& clip_region);

  ClipResult clip(const PolygonWithHoles2& subject) const;

 private:
  std::vector<Loop2> loops_;  // every loop, region on its left
  Box2 box_;
};

PolygonSet2 intersection(const PolygonSet2& a, const PolygonSet2& b);
PolygonSet2 difference(const PolygonSet2& a, const PolygonSet2& b);

}  // namespace shadowgen::clipper
