#pragma once

// A polygon against which many pieces are clipped (a template of hidden-surface removal,
// a receiver's image in shadow generation's coplanar pass): exact orientation tests
// against its convex hull, and against a piece when that is convex, settle the common
// cases (a piece beside it, a piece wholly within it) without calling the clipper. In a city seen
// from the sun most pairs whose bounding boxes overlap are faces that only share an edge or a
// corner's neighbourhood, or lie wholly in one another's shadow.

#include <optional>

#include "clipper/clip.h"
#include "clipper/polygon.h"

namespace shadowgen::hsr {

class ConvexWindow {
 public:
  // `window` must outlive this object. Not for use from several threads at once: the
  // window is prepared for the clipper (clipper::ClipRegion) when first needed.
  explicit ConvexWindow(const clipper::PolygonWithHoles2& window);

  // What clipper::clip(subject, window) gives, up to vertices where a boundary runs
  // straight on: where every vertex of the subject lies on or outside one edge line of the
  // window's convex hull (or every window vertex on or outside one edge line of a convex
  // subject), the two share no area and inside is empty; where every vertex of the
  // subject lies on or inside every edge line of a convex window without holes, the
  // subject is inside whole. Both are decided by exact predicates; anything else goes to
  // the clipper.
  clipper::ClipResult clip(const clipper::PolygonWithHoles2& subject) const;

  // The two tests clip() makes before the clipper, on their own: whether the subject and
  // the window share no area, and whether the subject lies inside the window whole.
  bool apart_from(const clipper::PolygonWithHoles2& subject) const;
  bool holds(const clipper::PolygonWithHoles2& subject) const;
  // clip(), but nothing where the subject lies beside the window (apart_from): a caller
  // that keeps such a subject as it is does without the copy clip() returns.
  std::optional<clipper::ClipResult> clip_unless_apart(
      const clipper::PolygonWithHoles2& subject) const;

 private:
  const clipper::PolygonWithHoles2& window_;
  int turn_ = 0;         // +1: outer loop convex counter-clockwise, -1: clockwise, 0: not convex
  clipper::Loop2 hull_;  // the outer loop's convex hull, counter-clockwise, when not convex
  mutable std::optional<clipper::ClipRegion> region_;  // the window, once a clip needs it
};

// +1 or -1 when `loop` is a convex loop turning that way (orient2d's sign), straight runs
// allowed; 0 when it is not convex, turns back on itself, repeats a vertex or has no area.
int convex_turn(const clipper::Loop2& loop);

}  // namespace shadowgen::hsr
