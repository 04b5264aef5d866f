#pragma once

// The one tolerance of the clipper: how near two points, or a point and an edge, may lie
// and still be taken as meeting. Each point p owns a hot pixel, the square
//     |x − p.x| ≤ 12u·m,  |y − p.y| ≤ 12u·m,   m = max(|p.x|, |p.y|),  u = 2^-53,
// six ulps of the point's own magnitude: it does not grow with the length of an edge,
// nor with coordinates elsewhere. It is derived, not chosen: each coordinate of a rounded
// crossing lies within 5u of its own magnitude of the exact one (detail/crossing.h), so
// the exact crossing lies in the rounded one's pixel, and every edge passing through that
// pixel must be routed through the crossing, or the rounding could carry it across that
// edge and turn the boundary between them inside out. Anything farther is a genuine
// feature and is left alone.
//
// The pixel is square, not six ulps of each coordinate apart: beside an axis a pixel
// that narrow in one direction is far thinner than the spacing of the doubles in the
// other, and points an ulp apart along the axis (with nothing representable between
// them) but a hair apart across it could be neither merged nor separated by a rounded
// crossing, leaving edges that cross.

#include "clipper/point.h"

namespace shadowgen::clipper::detail {

struct Pixel {
  double xmin, xmax, ymin, ymax;
};
Pixel hot_pixel(const Point2& p);

// The largest half-width of p's pixel: a margin for candidate searches.
double snap_distance(const Point2& p);

// Whether p and q (distinct) meet: one lies in the other's pixel.
bool within_snap_distance(const Point2& p, const Point2& q);

// Whether v projects strictly between the ends of e0-e1, measured from each end: from
// the far one alone, a point a hair before the near end (relative to the edge's length)
// rounds to the end itself. False at the ends.
bool projects_inside(const Point2& v, const Point2& e0, const Point2& e1);

// Whether v lies strictly between the edge's ends (by projection) and the edge passes
// through v's pixel (exactly through v included). Decided by exact orientation tests on
// the pixel's corners.
bool within_snap_distance(const Point2& v, const Point2& e0, const Point2& e1);

}  // namespace shadowgen::clipper::detail
