#include "snap_convergence.h"

#include <algorithm>
#include <atomic>
#include <cstddef>

#include "clipper/clip.h"
#include "clipper/predicates.h"
#include "close_pairs.h"
#include "snap_contacts.h"

namespace shadowgen::clipper::detail {
namespace {

// Rounds of changes after which the snapping looks for an end. A round looks only at
// what the previous one changed; a second round finds something on near-degenerate input
// only, a third was seen on adversarial input alone. Inputs that cycle are known: a
// route that came back to a point it passes had the stretch between cut out, and the
// points cut out were found in its way again, round after round (on self-crossing
// boundaries, and where dozens of rounded crossings crowd within a few pixels, as the
// shadow edges of a sun path fanning out from one corner do). The rounds first keep
// points cut out of a route out of it (snap_rounding.h); where they run again putting
// them back, the cycles seen passed through states whose edges meet only at vertices
// (noded, snap_convergence.h), so past the limit the rounds go on until one of them is
// reached, for kSearchRounds more at most: one that was seen lasted six rounds, and half
// of its states were noded.
constexpr int kMaxRounds = 17;
constexpr int kSearchRounds = 34;

// The bounds in force: these but while a SnapRoundLimitForTesting lives (clip.h).
std::atomic<int> round_limit{kMaxRounds};
std::atomic<int> search_rounds{kSearchRounds};
std::atomic<bool> grid_allowed{true};

// Whether two edges meet only at a common endpoint or as the very same segment (exact):
// no proper crossing, no endpoint of one inside the other.
bool meet_at_vertices(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1) {
  if ((a0 == b0 && a1 == b1) || (a0 == b1 && a1 == b0)) return true;
  auto inside = [](const Point2& p, const Point2& e0, const Point2& e1) {
    return p != e0 && p != e1 && on_segment(e0, e1, p);
  };
  if (inside(b0, a0, a1) || inside(b1, a0, a1) || inside(a0, b0, b1) || inside(a1, b0, b1)) {
    return false;
  }
  return !properly_cross(a0, a1, b0, b1);
}

}  // namespace

int snap_round_limit() { return round_limit.load(std::memory_order_relaxed); }

int snap_round_search() { return search_rounds.load(std::memory_order_relaxed); }

bool snap_on_grid_allowed() { return grid_allowed.load(std::memory_order_relaxed); }

bool noded(const std::vector<Loop2> (&loops)[2]) {
  struct Edge {
    Point2 from, to;
  };
  std::vector<Edge> edges;
  for (const auto& side : loops) {
    for (const Loop2& loop : side) {
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2& to = loop[i + 1 == loop.size() ? 0 : i + 1];
        if (loop[i] != to) edges.push_back({loop[i], to});
      }
    }
  }
  bool all = true;
  for_each_close_pair(
      edges, [](std::size_t) { return 0.0; }, [](std::size_t) { return true; },
      [&](std::size_t i, std::size_t j) {
        all = all && meet_at_vertices(edges[i].from, edges[i].to, edges[j].from, edges[j].to);
      });
  return all;
}

}  // namespace shadowgen::clipper::detail

namespace shadowgen::clipper {

// The test hook of clip.h, here beside the limit it sets.
SnapRoundLimitForTesting::SnapRoundLimitForTesting(int rounds, int search, bool on_grid)
    : previous_(detail::round_limit.exchange(std::max(rounds, 0))),
      previous_search_(detail::search_rounds.exchange(std::max(search, 0))),
      previous_on_grid_(detail::grid_allowed.exchange(on_grid)) {}

SnapRoundLimitForTesting::~SnapRoundLimitForTesting() {
  detail::round_limit.store(previous_);
  detail::search_rounds.store(previous_search_);
  detail::grid_allowed.store(previous_on_grid_);
}

}  // namespace shadowgen::clipper
