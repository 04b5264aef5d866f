#pragma once

// The one tolerance of the clipper: how far a vertex may lie off an edge and still be
// taken as lying on it. It is derived, not chosen: twice the error bound of one rounded
// crossing point (clip.h), 2·(4u·|edge| + u·|P|) with u = 2^-53 and |P| the largest
// coordinate magnitude of the edge. A vertex that an earlier clip constructed on an edge
// lies within it; anything farther is a genuine feature and is left alone.

#include "clipper/point.h"

namespace shadowgen::clipper::detail {

double snap_distance(const Point2& e0, const Point2& e1);

// Whether v lies strictly between the edge's ends (by projection) and within
// snap_distance of the segment (exactly on it included).
bool within_snap_distance(const Point2& v, const Point2& e0, const Point2& e1);

}  // namespace shadowgen::clipper::detail
