#pragma once

// The part of a box on one side of a line, as a convex polygon the clipper can use.

#include "clipper/box.h"
#include "clipper/polygon.h"

namespace shadowgen::hsr::detail {

// The region {a·x + b·y + c >= 0} within `box` (grown by its own size on every side, so
// that polygons inside the box are far from its border). Empty when none of it is there.
clipper::PolygonWithHoles2 half_plane_in_box(double a, double b, double c,
                                             const clipper::Box2& box);

}  // namespace shadowgen::hsr::detail
