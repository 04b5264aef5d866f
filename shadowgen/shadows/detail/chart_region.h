#pragma once

// A region of a face part's plane chart (what one light, or one instant of a sun path,
// lights of the part), held with its complement in the part, so that the part's pieces
// are sorted into the region's inside and outside with as little clipping as possible.
// The light-set regions (light_regions.h) and the sun-hours regions (sun_hours.h) split
// a part's pieces by one light or instant after another this way: over many lights most
// pieces lie far from any one light's shadow edges, and the work per light then follows
// those edges, not the pieces.

#include <vector>

#include "clipper/box.h"
#include "clipper/polygon.h"

namespace shadowgen::shadows::detail {

class ChartRegion {
 public:
  // `whole`: the part in its chart; `inside`: the region's polygons, within the part. The
  // complement, whole − inside, is clipped here once, for its boxes. Throws
  // clipper::SnapRoundingError where that clip's snapping does not settle.
  ChartRegion(const clipper::PolygonSet2& whole, clipper::PolygonSet2 inside);

  // Appends what of `pieces` (pieces of the part, not overlapping) lies inside the region
  // to `inside`, the rest to `outside`. A piece whose box meets none of the region's
  // polygons' boxes goes to `outside` whole, one whose box meets none of the
  // complement's to `inside` whole, each as it is. So does a piece whose boundary the
  // region's does not pass through, where it lies (clipper/placement.h, exact); only the
  // rest are clipped, against the region's polygons that their boxes meet, never the
  // complement (whose edges are the region's as a clip rounded them). Under many lights
  // or instants that makes the work follow the shadow edges rather than the pieces. The
  // pieces left whole keep their vertices while their neighbours are cut: where the
  // edges of many lights fan out from nearly one point (a shadow's tip at a building's
  // foot, a little off from instant to instant) pieces can come out as slivers meeting
  // within 1e-13 of one another, which the clipper's snapping takes (docs/clipper.md,
  // Limit). Pieces of one call that share edges may come out merged, so give one call
  // pieces that may merge (one light set, one count). The result is exact up to the
  // clipper's rounding of crossing points (clipper/clip.h). Throws
  // clipper::SnapRoundingError as clip() does.
  void split(clipper::PolygonSet2 pieces, clipper::PolygonSet2& outside,
             clipper::PolygonSet2& inside) const;

 private:
  clipper::PolygonSet2 inside_;
  std::vector<clipper::Box2> inside_boxes_;
  std::vector<clipper::Box2> outside_boxes_;  // of the part's complement of the region
};

}  // namespace shadowgen::shadows::detail
