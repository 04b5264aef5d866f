#pragma once

// Metamorphic transforms of whole regions: a translation or a uniform scale of a valid
// region, applied in double arithmetic. Each coordinate is rounded once, so the result
// is a slightly different (still valid, for the moderate factors used in the tests)
// region; compare it with the oracle's answer for the transformed input, not with the
// original's.

#include "clipper/polygon.h"

namespace shadowgen::test {

clipper::PolygonSet2 translated(const clipper::PolygonSet2& polygons, clipper::Point2 offset);
clipper::PolygonSet2 scaled(const clipper::PolygonSet2& polygons, double factor);

}  // namespace shadowgen::test
