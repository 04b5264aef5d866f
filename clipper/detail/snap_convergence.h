#pragma once

// When the snapping stops (snap_rounding.h): the bound on its rounds, and the exact check
// that decides whether what a stopped snapping leaves is still usable. Kept apart from
// the snapping itself because it judges the result rather than producing it, and because
// the test hook of clip.h (SnapRoundLimitForTesting) sets the bound here.

#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

// The number of rounds of changes after which the snapping stops at the first state whose
// edges are noded, and the number of rounds more it may take to reach one: fixed bounds,
// but while a SnapRoundLimitForTesting (clipper/clip.h) lives.
int snap_round_limit();
int snap_round_search();

// Whether the snapping may fall back on a grid (grid_snap.h) where the rounds end with
// edges crossing: always, but while a SnapRoundLimitForTesting that forbids it lives.
bool snap_on_grid_allowed();

// Whether the loops' edges all meet only at vertices: the plane graph the overlay needs,
// which a round limit can leave the snapping short of.
bool noded(const std::vector<Loop2> (&loops)[2]);

}  // namespace shadowgen::clipper::detail
