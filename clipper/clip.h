#pragma once

// The Weiler–Atherton clipper (Weiler and Atherton 1977; Atherton, Weiler and Greenberg
// 1978, section III): its method, input and output, exactness, tolerance, limit and cost
// are docs/clipper.md.

#include <cstddef>
#include <span>
#include <stdexcept>

#include "clipper/box.h"
#include "clipper/polygon.h"

namespace shadowgen::clipper {

// The snapping ended with edges still meeting elsewhere than at common vertices, after
// the rounds and the grid both (docs/clipper.md, "Limit"): thrown by clip(), intersection(),
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

// The inside and outside pieces of a concave subject with holes against a concave clip
// with holes. The operands' regions must be well formed (loops simple, holes inside their
// outer loop, loops meeting at most at points), of either orientation; the pieces are in
// clipper/polygon.h's conventions, every loop simple. Decisions are exact; new points are
// crossings within 5u of their magnitude, and the boundary moves by at most a hot pixel
// where snapping rounds it (docs/clipper.md). Throws SnapRoundingError where the snapping
// does not settle.
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
