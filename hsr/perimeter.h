#pragma once

// Perimeters of 3D polygons: the lengths of their loops' edges, holes included. Rounding
// bounds are perimeters times how far rounding can move a point (a boundary moved by r
// sweeps at most r × its length of area).

#include "hsr/polygon3.h"

namespace shadowgen::hsr {

// The length of the closed loop (its last vertex joined back to its first); 0 for fewer
// than two vertices. Any finite coordinates (hsr/vector_length.h).
double perimeter(const Loop3& loop);

// The outer loop's perimeter plus every hole's.
double perimeter(const Polygon3& polygon);

}  // namespace shadowgen::hsr
