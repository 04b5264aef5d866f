#pragma once

// Snap rounding's rounds (snap_rounding.h): each input edge routed through the points
// found in its way, round after round, until no piece meets another but at a common
// endpoint, or the round limit stops them (snap_convergence.h).

#include <vector>

#include "clipper/polygon.h"
#include "snap_rounding.h"

namespace shadowgen::clipper::detail {

// Runs the rounds on the loops (loops[0] the subject's, loops[1] the clip's) and puts in
// `snapped` the loops with each edge replaced by its route as the rounds left it, settled
// or not: whether that is a plane graph is the caller's to check (noded,
// snap_convergence.h). `hold_back`: points cut out of a route are kept out of it.
// Returns what the rounds did; `converged` false where the limit stopped them or points
// were held back.
SnapRoundingStats snap_round_in_rounds(const std::vector<Loop2> (&loops)[2], bool hold_back,
                                       std::vector<Loop2> (&snapped)[2]);

}  // namespace shadowgen::clipper::detail
