#pragma once

// SVG path data (a path's d attribute) of polygons with holes, each loop a closed subpath,
// in one of two forms (svg_writer.h says which output takes which):
//
//   exact   absolute commands, "M x,y L x,y x,y ... Z", each coordinate the shortest
//           decimal that reads back to the same double (std::to_chars): what the picture
//           holds, at any zoom.
//   grid    each vertex rounded to the nearest point of a grid of 1/kPathGrid pixel, then
//           written relative to the one before ("m" from the previous subpath's start,
//           "l" or, along an axis, "h" and "v"), each number the whole steps of the grid it
//           moves, with no more digits than they need ("m12.5,3l.25-1.125h3z"). After the
//           rounding, a vertex equal to the one before, or on the straight line through its
//           neighbours, is dropped (exactly, in whole steps: the rounded loop's area stays
//           what it is), and a loop with no area left is dropped.
//
// What the grid costs (docs/scene-format.md, "Maps"): each coordinate moves by at most half
// a step, h = 1/(2 kPathGrid) pixel, so each vertex by at most δ = √2·h, and a loop of n
// vertices and perimeter P changes its area by at most δ·P + n·δ²/2 (the shoelace formula
// of the moved vertices; the vertices dropped afterwards change nothing).
//
// A path with a coordinate 2^30 steps (a million pixels) or more from the origin, where
// whole steps could no longer be multiplied exactly in 64 bits, is written exact.

#include <span>
#include <string>

#include "clipper/polygon.h"

namespace shadowgen::view::detail {

inline constexpr double kPathGrid = 1000.0;  // steps per pixel

void append_exact_path_data(std::string& out, std::span<const clipper::PolygonWithHoles2> shapes);

void append_grid_path_data(std::string& out, std::span<const clipper::PolygonWithHoles2> shapes);

}  // namespace shadowgen::view::detail
