#pragma once

// Loops, polygons with holes and sets of them: the clipper's vocabulary.
//
// Conventions (what every function of clipper/ returns, and what `normalized` makes
// of any valid input):
//   - a Loop is a closed ring of vertices, the closing edge implied (last -> first);
//   - the outer loop of a PolygonWithHoles2 runs counter-clockwise, its holes clockwise,
//     so the polygon's region always lies to the left of every directed edge;
//   - holes lie inside their outer loop; loops of one polygon, and polygons of one set,
//     meet at most at isolated points (never along an edge, never crossing).

#include <utility>
#include <vector>

#include "clipper/point.h"

namespace shadowgen::clipper {

using Loop2 = std::vector<Point2>;

struct PolygonWithHoles2 {
  Loop2 outer;
  std::vector<Loop2> holes;

  // The same loops, vertex for vertex, in the same order.
  friend bool operator==(const PolygonWithHoles2&, const PolygonWithHoles2&) = default;
};

// A region made of disjoint polygons with holes (a "multipolygon").
using PolygonSet2 = std::vector<PolygonWithHoles2>;

// Signed area by the shoelace formula: positive for counter-clockwise loops.
double signed_area(const Loop2& loop);
// Region area: |outer| minus the holes.
double area(const PolygonWithHoles2& polygon);
double area(const PolygonSet2& polygons);

// How much area the rounding of a loop's constructed vertices can account for: each moves
// by at most its hot pixel, 12u of its largest coordinate's magnitude (clip.h), sweeping at most
// that times the perimeter, below 18u·(max |coordinate| + 4·perimeter)·perimeter in all
// (u = 2^-53; the perimeter term covers loops far smaller than their coordinates' scale,
// which is what the pixel is measured in). A loop of smaller
// area is thinner than the rounding of its own coordinates: it may exist only because of
// rounding, and nothing can tell it from an empty one.
double rounding_area_bound(const Loop2& loop);

std::size_t vertex_count(const PolygonWithHoles2& polygon);
std::size_t vertex_count(const PolygonSet2& polygons);

// `set` with every loop, outer and holes alike, replaced by `map(loop)`: a set carried
// pointwise into other coordinates.
template <class MapLoop>
PolygonSet2 map_loops(const PolygonSet2& set, MapLoop&& map) {
  PolygonSet2 out;
  out.reserve(set.size());
  for (const PolygonWithHoles2& p : set) {
    PolygonWithHoles2 q{map(p.outer), {}};
    q.holes.reserve(p.holes.size());
    for (const Loop2& h : p.holes) q.holes.push_back(map(h));
    out.push_back(std::move(q));
  }
  return out;
}

}  // namespace shadowgen::clipper
