#pragma once

// Validity of a face's loops in its plane chart (plane_chart.h), decided exactly with
// clipper::orient2d:
//   - every loop is simple: no two edges meet except consecutive ones at their shared
//     vertex (an edge that doubles back along its predecessor counts as meeting it);
//   - holes lie inside the outer loop, and holes' interiors are disjoint; loops may touch
//     at isolated points, but neither cross nor run along each other.
// Consecutive repeated vertices are ignored (they add no edge).
//
// Cost: edges are paired by a sort-and-sweep over their bounding boxes, and only pairs
// whose boxes overlap are tested, so ordinary loops take O(n log n); loops whose boxes
// all overlap (long parallel slivers) degrade towards O(n^2) cheap box tests. Each hole
// costs one point-in-polygon test against the outer loop, and one against every hole
// whose box contains its box.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::detail {

struct LoopCheck {
  // What is wrong, naming loops by `loop_names` and vertices by their index in the given
  // loop; empty when the loops are valid.
  std::optional<std::string> problem;
  // Per loop, when valid: whether it runs counter-clockwise in the chart.
  std::vector<bool> counter_clockwise;
};

// loops[0] is the outer loop, the others are holes (either orientation); each has at
// least three distinct vertices. loop_names has one entry per loop, e.g. "outer loop",
// "hole 2".
LoopCheck check_loops(std::span<const clipper::Loop2> loops,
                      std::span<const std::string> loop_names);

}  // namespace shadowgen::detail
