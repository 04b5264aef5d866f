#pragma once

// Areas of planar 3D polygons with holes, measured in their own plane.

#include <span>

#include "hsr/polygon3.h"

namespace shadowgen {

// Area of the region (outer minus holes) of a planar polygon, by the projected shoelace
// formula on the coordinate plane most facing it, relative to the first vertex.
double area(const hsr::Polygon3& polygon);
double area(std::span<const hsr::Polygon3> polygons);

}  // namespace shadowgen
