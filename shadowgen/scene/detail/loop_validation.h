#pragma once

// Validity of a face's loops in its plane chart (plane_chart.h), decided exactly with
// clipper::orient2d:
//   - every loop bounds a region without crossing itself. It may pass through one point
//     more than once (pinched, common in mesh faces) and may run along one edge once each
//     way (a bridge to an inner boundary, as a keyhole cut makes), as long as it does not
//     cross over there and covers no area twice: it stands for the region it bounds. Any
//     other meeting of two of its edges is an error: a crossing, a vertex on another
//     edge, edges running along each other otherwise, or an edge that doubles back along
//     its predecessor;
//   - holes lie inside the outer loop, and holes' interiors are disjoint; loops may touch
//     at isolated points and may share segments of their edges (a door at the foot of a
//     wall, two windows side by side), but never cross.
// Consecutive repeated vertices are ignored (they add no edge).
//
// Two loops that share a segment have directions in common where they meet, so their
// sides cannot be told from their directions there (below). For such a pair, whether the
// hole lies inside the outer loop, or whether two holes overlap, is decided by the
// clipper (clipper/clip.h) on the loops as given: the hole less the outer loop, or the
// two holes' intersection, must be empty. With no crossing the clipper makes no new
// point, so its answer is exact but for the hot pixels of its snapping: a piece thinner
// than the rounding of its coordinates (clipper::rounding_area_bound) counts as empty.
// Every other pair of loops is checked exactly as below.
//
// How a pinched or bridged loop is checked: at every point it passes more than once, no
// two of its passages may cross (their directions in and out must not interleave around
// the point). With the bridges taken out (each pair of opposite runs along one edge), the
// loop falls into closed pieces that meet only at points; around every point the edges
// into and out of it must alternate, and each piece must lie where the others leave the
// winding number at 0 on its outside: then the winding number is 0 or ±1 everywhere, and
// the loop could be pulled apart into a simple one.
//
// Cost: edges are paired by a sort-and-sweep over their bounding boxes, and only pairs
// whose boxes overlap are tested, so ordinary loops take O(n log n); loops whose boxes
// all overlap (long parallel slivers) degrade towards O(n^2) cheap box tests. Each hole
// costs one point-in-polygon test against the outer loop, and one against every hole
// whose box contains its box. A loop that falls into k pieces costs k - 1 winding-number
// tests more. Each pair of loops that share a segment costs one clip.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::scene::detail {

struct LoopCheck {
  // What is wrong, naming loops by `loop_names` and vertices by their index in the given
  // loop; empty when the loops are valid.
  std::optional<std::string> problem;
  // Per loop, when valid: whether it runs counter-clockwise in the chart (for a pinched or
  // bridged loop: whether the region it bounds lies to its left).
  std::vector<bool> counter_clockwise;
  // When valid: whether two loops share a segment of positive length. The loops are then
  // no polygon with holes in the clipper's sense (clipper/polygon.h), and no input for
  // clipper::triangulate: their region is to be computed (shared_edge_region.h).
  bool shares_edges = false;
};

// loops[0] is the outer loop, the others are holes (either orientation); each has at
// least three distinct vertices. loop_names has one entry per loop, e.g. "outer loop",
// "hole 2".
LoopCheck check_loops(std::span<const clipper::Loop2> loops,
                      std::span<const std::string> loop_names);

}  // namespace shadowgen::scene::detail
