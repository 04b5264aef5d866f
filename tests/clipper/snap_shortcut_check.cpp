#include "tests/clipper/snap_shortcut_check.h"

#include <vector>

#include "clipper/clip.h"
#include "clipper/detail/snap_rounding.h"
#include "clipper/normalize.h"
#include "tests/support/wkt.h"

namespace shadowgen::test {
namespace {

// The loops of an operand as clip() hands them to snap rounding: normalized, every loop
// with its region on the left.
std::vector<clipper::Loop2> boundary(const clipper::PolygonSet2& polygons) {
  std::vector<clipper::Loop2> loops;
  for (const clipper::PolygonWithHoles2& p : clipper::normalized(polygons)) {
    loops.push_back(p.outer);
    for (const clipper::Loop2& h : p.holes) loops.push_back(h);
  }
  return loops;
}

std::string loops_text(const std::vector<clipper::Loop2>& loops) {
  clipper::PolygonSet2 as_polygons;
  for (const clipper::Loop2& loop : loops) as_polygons.push_back({loop, {}});
  return to_wkt(as_polygons);
}

}  // namespace

std::string shortcut_disagreement(const clipper::PolygonSet2& subject,
                                  const clipper::PolygonSet2& clip, bool* taken) {
  using clipper::detail::SnapPath;
  using clipper::detail::SnapRoundingStats;
  const std::vector<clipper::Loop2> input[2] = {boundary(subject), boundary(clip)};
  std::vector<clipper::Loop2> shortcut[2] = {input[0], input[1]};
  std::vector<clipper::Loop2> rounds[2] = {input[0], input[1]};
  SnapRoundingStats by_shortcut, by_rounds;
  try {
    clipper::detail::snap_round(shortcut, &by_shortcut, SnapPath::kShortcutWhereShown);
  } catch (const clipper::SnapRoundingError&) {
    by_shortcut.separated = false;  // the rounds' own failure: nothing to compare
  }
  if (taken != nullptr) *taken = by_shortcut.separated;
  if (!by_shortcut.separated) return "";
  try {
    clipper::detail::snap_round(rounds, &by_rounds, SnapPath::kRoundsOnly);
  } catch (const clipper::SnapRoundingError& e) {
    return std::string("the shortcut decided where the rounds fail: ") + e.what();
  }
  std::string differences;
  for (int side = 0; side < 2; ++side) {
    if (shortcut[side] != rounds[side]) {
      differences += (side == 0 ? "subject" : "clip") + std::string(" loops: shortcut ") +
                     loops_text(shortcut[side]) + ", rounds " + loops_text(rounds[side]) + "; ";
    }
  }
  if (by_shortcut.rounds != by_rounds.rounds || by_shortcut.crossings != by_rounds.crossings ||
      by_shortcut.splits != by_rounds.splits || !by_rounds.converged) {
    differences += "statistics: shortcut " + std::to_string(by_shortcut.rounds) + " rounds, " +
                   std::to_string(by_shortcut.crossings) + " crossings, " +
                   std::to_string(by_shortcut.splits) + " splits; rounds " +
                   std::to_string(by_rounds.rounds) + ", " + std::to_string(by_rounds.crossings) +
                   ", " + std::to_string(by_rounds.splits) +
                   (by_rounds.converged ? "" : ", not converged");
  }
  return differences;
}

}  // namespace shadowgen::test
