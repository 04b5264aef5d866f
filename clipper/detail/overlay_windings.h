#pragma once

// The winding numbers of the overlay graph's faces (overlay.h): every edge gets those of
// the faces on its right, spread exactly from vertex to vertex along the edges, each
// connected part starting from the sector straight left of its lowest-leftmost vertex,
// located against the other parts' loops by exact point location.

#include <vector>

#include "clipper/polygon.h"
#include "overlay_graph.h"

namespace shadowgen::clipper::detail {

// Sets `right` (and `known`) on every edge of `graph`, built from these loops by
// build_overlay_graph. Uses the graph's part, seeds, stack, todo and done as scratch.
void spread_windings(const std::vector<Loop2> (&loops)[2], OverlayGraph& graph);

}  // namespace shadowgen::clipper::detail
