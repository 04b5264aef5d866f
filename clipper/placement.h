#pragma once

// Where a polygon lies against a region when the region's boundary does not pass through
// the polygon's interior, decided exactly (clipper/segment_contact.h, winding numbers by
// orient2d), without clipping. Boundaries may touch and share edges: pieces cut along a
// shadow's edge by one light often share that edge with another light's shadow. Used to
// sort many small pieces by a region where most of them lie away from its edges, or
// only touch them (shadowgen/shadows/detail/chart_region.h).

#include <span>

#include "clipper/polygon.h"

namespace shadowgen::clipper {

enum class Placement {
  kInside,   // every point of the polygon is inside the region
  kOutside,  // none is
  kMeeting,  // the boundaries meet (cross, touch or overlap), or the polygon holds a
             // loop of the region: clip to know
};

// `polygon` (a valid polygon with holes: clipper/polygon.h, the outer loop in either
// orientation, holes against it) against the region that is the union of `region`
// (polygons of the same kind, which may overlap one another). Every region polygon that can meet
// `polygon` must be given; others may be. No rounding: the answer is the exact one for
// the given coordinates.
Placement placement(const PolygonWithHoles2& polygon,
                    std::span<const PolygonWithHoles2* const> region);

}  // namespace shadowgen::clipper
