// Snap rounding's order of ways: the shortcut where it is shown (snap_shortcut.h), else
// the rounds holding points back and then putting them back (snap_rounds.h), else the
// grid (grid_snap.h); each way's result is taken only where the exact check finds it
// noded.

#include "snap_rounding.h"

#include <string>
#include <utility>

#include "clipper/clip.h"
#include "grid_snap.h"
#include "snap_convergence.h"
#include "snap_rounds.h"
#include "snap_shortcut.h"

namespace shadowgen::clipper::detail {

void snap_round(std::vector<Loop2> (&loops)[2], SnapRoundingStats* stats, SnapPath path) {
  if (path == SnapPath::kShortcutWhereShown && snap_round_separated(loops, stats)) return;
  // Points cut out of routes held back first: that ends the cycles of cuts. Where it
  // leaves edges crossing, the rounds again putting points back, cycles and all, which
  // pass through noded states (snap_convergence.cpp): each way settled inputs the other
  // did not. Either way's result is taken only where the exact check finds it noded,
  // settled or not: the rounds look again only at pairs with a piece changed in the
  // last round, and a route held back has left a crossing unseen that way (regression
  // rounds-settled-short-of-a-crossing-by-a-corner).
  SnapRoundingStats local;
  for (const bool hold_back : {true, false}) {
    std::vector<Loop2> snapped[2];
    local = snap_round_in_rounds(loops, hold_back, snapped);
    if (stats != nullptr) *stats = local;
    if (noded(snapped)) {
      loops[0] = std::move(snapped[0]);
      loops[1] = std::move(snapped[1]);
      return;
    }
  }
  // Neither way reached a plane graph: snap rounding on a grid does by construction,
  // moving every vertex further (grid_snap.h).
  if (snap_on_grid_allowed()) {
    std::vector<Loop2> gridded[2] = {loops[0], loops[1]};
    snap_round_on_grid(gridded);
    if (stats != nullptr) stats->on_grid = true;
    if (noded(gridded)) {
      loops[0] = std::move(gridded[0]);
      loops[1] = std::move(gridded[1]);
      return;
    }
  }
  std::size_t edges = 0;
  for (const auto& side : loops) {
    for (const Loop2& loop : side) edges += loop.size();
  }
  throw SnapRoundingError("snap rounding of " + std::to_string(edges) +
                          " edges did not settle within " + std::to_string(local.rounds) +
                          " rounds: edges still meet elsewhere than at common vertices");
}

}  // namespace shadowgen::clipper::detail
