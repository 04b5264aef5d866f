#pragma once

// Snap rounding's shortcut (snap_rounding.h): the common case of operands of a few edges
// that meet only where edges cross properly or where a vertex lies in an edge's way,
// every other point well clear of every edge, decided and snapped without rounds.

#include <vector>

#include "clipper/polygon.h"
#include "snap_rounding.h"

namespace shadowgen::clipper::detail {

// Where the loops (loops[0] the subject's, loops[1] the clip's) are shown to be such a
// case, routes each edge through the points found on it, in order along it, fills
// `stats` (if given; `separated` set) and returns true: the loops the rounds would give
// (SnapRound.TheShortcutGivesWhatTheRoundsGive). Otherwise returns false, the loops and
// `stats` as they came.
bool snap_round_separated(std::vector<Loop2> (&loops)[2], SnapRoundingStats* stats);

}  // namespace shadowgen::clipper::detail
