#pragma once

// The analysis of one pinched or bridged loop (loop_validation.h says what such loops
// are and why they are accepted). With its bridges taken out (each pair of opposite runs
// along one edge), the loop falls into closed pieces that meet only at points. It bounds
// a region, and could be pulled apart into a simple loop, when around every point the
// edges into and out of it alternate, and each piece lies where the others leave the
// winding number at 0 on its outside: then the winding number is 0 or ±1 everywhere.
//
// Kept apart from the checks between loops because it looks at one loop alone, and its
// result (the pieces) is what those checks then use at the points where loops touch.

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "clipper/polygon.h"
#include "loop_geometry.h"

namespace shadowgen::scene::detail {

// A pinched or bridged loop with its bridges taken out: after each edge into a point,
// the edge out of it that the loop takes next, jumping over bridges.
struct LoopPieces {
  std::vector<std::uint32_t> next_edge;                            // by edge; kNoEdge for bridges
  std::map<clipper::Point2, std::vector<std::uint32_t>> edges_in;  // edges ending at each point
};

struct PiecesCheck {
  // What is wrong, naming the loop by the given name and vertices by their index in the
  // given loop; empty when the loop bounds a region.
  std::optional<std::string> problem;
  // When it does: whether the region lies to its left.
  bool counter_clockwise = false;
};

// `bridge_partner` gives, per edge of `loop`, the edge that runs along it the other way
// (kNoEdge for none), or is empty when the loop has no bridges. Fills `pieces`, which the
// checks at touching points read afterwards.
PiecesCheck check_pieces(const CleanLoop& loop, std::span<const std::uint32_t> bridge_partner,
                         const std::string& name, LoopPieces& pieces);

}  // namespace shadowgen::scene::detail
