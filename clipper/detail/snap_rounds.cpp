// Snap rounding's rounds: the routes of the input edges, the pieces of them each round
// looks at, and the changes a round makes (points put in, vertices merged, slivers cut).

#include "snap_rounds.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "clipper/predicates.h"
#include "close_pairs.h"
#include "crossing.h"
#include "loop_of_routes.h"
#include "snap.h"
#include "snap_contacts.h"
#include "snap_convergence.h"

namespace shadowgen::clipper::detail {
namespace {

// An upper bound on how far p lies from the line through a0 and a1. First in doubles: the
// cross product is within 4u·permanent of the exact one (orient2d's filter), added rather
// than resolved, this being a tolerance on the path of every moved piece. Along a long
// edge that slack (u times the edge's length) can exceed the pixels of the points the
// piece passes, and a band that wide would route the piece through vertices it never
// came near: then the cross product is taken rounded once from its exact value.
double distance_to_line(const Point2& p, const Point2& a0, const Point2& a1) {
  if (p == a0 || p == a1) return 0.0;
  const double dx = a1.x - a0.x, dy = a1.y - a0.y;
  const double length = std::sqrt(dx * dx + dy * dy);
  const double left = dx * (p.y - a0.y), right = dy * (p.x - a0.x);
  const double bound = std::fabs(left - right) + 0x1p-51 * (std::fabs(left) + std::fabs(right));
  const double coarse = 1.0001 * bound / length;
  if (coarse <= snap_distance(p)) return coarse;
  return 1.0001 * std::fabs(orient2d_value(a0, a1, p)) / length;
}

// Whether two rounded crossings on the edge from -> to lie within the sum of their
// roundings (5u of each coordinate's magnitude, crossing.h) of each other in the
// coordinate that varies most along it: then the rounding may have reversed their order.
bool near_each_other(const Point2& a, const Point2& b, const Point2& from, const Point2& to) {
  constexpr double k = 5.0 * 0x1p-53;
  if (std::fabs(to.x - from.x) >= std::fabs(to.y - from.y)) {
    return std::fabs(a.x - b.x) <= k * (std::fabs(a.x) + std::fabs(b.x));
  }
  return std::fabs(a.y - b.y) <= k * (std::fabs(a.y) + std::fabs(b.y));
}

class SnapRounder {
  // A point to put into a route, in the piece that ends at route[position].
  struct Insertion {
    std::uint32_t segment, position;
    Point2 at;
    bool crossing;  // with the edge f0-f1, this piece being its whole input edge
    Point2 f0, f1;
  };
  // A stretch of a route to cut out.
  struct Cut {
    std::uint32_t segment;
    std::size_t first, last;  // route[first, last) goes
  };

  // What one round changes in the routes.
  struct Changes {
    std::vector<Insertion> insertions;
    std::vector<Cut> cuts;
    bool held_back = false;  // a point found in a piece's way was not put back (plan)
  };

 public:
  // `hold_back`: points cut out of a route stay out of it (snap_rounding.h).
  SnapRounder(const std::vector<Loop2> (&loops)[2], bool hold_back) : hold_back_(hold_back) {
    for (int side = 0; side < 2; ++side) {
      for (const Loop2& loop : loops[side]) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
          segments_.push_back({loop[i], loop[i + 1 == loop.size() ? 0 : i + 1], {}});
        }
      }
    }
    changed_.assign(segments_.size(), 1);
    cut_out_.resize(segments_.size());
  }

  // `loops` are those the rounder was made from: their sizes tell write_back where each
  // loop ends.
  SnapRoundingStats run(const std::vector<Loop2> (&loops)[2]) {
    SnapRoundingStats stats;
    const int limit = snap_round_limit(), last = limit + snap_round_search();
    for (int round = 0;; ++round) {
      build_pieces();
      Contacts found;
      ContactFinder finder(pieces_, segments_, found);
      // Pairs of unchanged pieces were looked at when the younger of them was made.
      for_each_close_pair(
          pieces_, [this](std::size_t i) { return pieces_[i].margin; },
          [this](std::size_t i) { return pieces_[i].fresh; },
          [&finder](std::size_t i, std::size_t j) { finder.find(i, j); });
      if (found.through.empty() && found.merges.empty()) break;
      // Past the limit, stopped with this round's changes not made at the first state
      // whose edges meet only at vertices (snap_convergence.cpp: cycles pass through
      // such states), or at the last round allowed: snap_round then checks exactly.
      if (round >= limit && (round == last || noded_now(loops))) {
        stats.converged = false;
        break;
      }
      stats.crossings += found.crossings;
      const bool merged = apply_merges(found.merges);
      Changes changes = plan(found.through);
      const bool added = !changes.insertions.empty() || !changes.cuts.empty();
      apply(changes);
      if (!merged && !added) {
        // Nothing left to change but points held back: whether the edges meet only at
        // vertices is then checked exactly (snap_round), as where the limit stops it.
        stats.converged = !changes.held_back;
        break;
      }
      ++stats.rounds;
      stats.splits += changes.insertions.size();
      if (merged) {
        std::fill(changed_.begin(), changed_.end(), 1);
        resolve_routes();
      }
    }
    return stats;
  }

  // Whether the loops as the routes stand have edges meeting only at vertices.
  bool noded_now(const std::vector<Loop2> (&loops)[2]) const {
    std::vector<Loop2> snapped[2] = {loops[0], loops[1]};
    write_back(snapped);
    return noded(snapped);
  }

  // The loops, each edge replaced by its route.
  void write_back(std::vector<Loop2> (&loops)[2]) const {
    std::size_t k = 0;
    for (int side = 0; side < 2; ++side) {
      for (Loop2& loop : loops[side]) {
        const std::size_t n = loop.size();
        LoopOfRoutes out(n);
        for (std::size_t i = 0; i < n; ++i, ++k) {
          const Segment& s = segments_[k];
          out.add(resolve(s.from));
          for (const Point2& p : s.route) out.add(p);
        }
        loop = out.take();
      }
    }
  }

 private:
  // Each point goes into the piece it was found on, once per segment, so no two points
  // can take turns. A point the route already passes elsewhere (where an earlier round
  // put it) means the route comes back to it: the stretch between, a sliver loop
  // narrower than the pixels it passes, is cut out (one cut per route and round, and no
  // insertions into that route in the same round).
  Changes plan(const std::vector<Through>& through) const {
    Changes changes;
    std::vector<Insertion>& insertions = changes.insertions;
    std::vector<Cut>& cuts = changes.cuts;
    for (const Through& found_point : through) {
      const Point2& point = found_point.at;
      const Piece& e = pieces_[found_point.piece];
      const Segment& s = segments_[e.segment];
      const Point2 r = resolve(point);
      // Its place on the route extended by the segment's ends: 0 for the start,
      // j + 1 for route[j], route.size() + 1 for the end. The piece runs from place
      // e.position to place e.position + 1.
      std::size_t place = s.route.size() + 2;
      if (r == resolve(s.from)) {
        place = 0;
      } else if (r == resolve(s.to)) {
        place = s.route.size() + 1;
      } else {
        const auto it = std::find(s.route.begin(), s.route.end(), r);
        if (it != s.route.end()) place = static_cast<std::size_t>(it - s.route.begin()) + 1;
      }
      if (place == s.route.size() + 2) {
        const std::vector<Point2>& gone = cut_out_[e.segment];
        if (hold_back_ && std::find(gone.begin(), gone.end(), r) != gone.end()) {
          changes.held_back = true;
          continue;
        }
        insertions.push_back({e.segment, e.position, r, found_point.crossing && r == point,
                              found_point.f0, found_point.f1});
        continue;
      }
      const std::size_t p = e.position;
      const Cut cut = place <= p ? Cut{e.segment, place, p} : Cut{e.segment, p, place - 1};
      if (cut.first < cut.last) cuts.push_back(cut);
    }
    if (!cuts.empty()) {
      std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) {
        // The shortest cut of a route first: it removes the least.
        if (a.segment != b.segment) return a.segment < b.segment;
        if (a.last - a.first != b.last - b.first) return a.last - a.first < b.last - b.first;
        return a.first < b.first;
      });
      cuts.erase(std::unique(cuts.begin(), cuts.end(),
                             [](const Cut& a, const Cut& b) { return a.segment == b.segment; }),
                 cuts.end());
      std::vector<char> cut_here(segments_.size(), 0);
      for (const Cut& cut : cuts) cut_here[cut.segment] = 1;
      std::erase_if(insertions, [&cut_here](const Insertion& in) { return cut_here[in.segment]; });
    }
    return changes;
  }

  // Puts the points in and cuts the stretches out.
  void apply(Changes& changes) {
    insert(changes.insertions);
    for (const Cut& cut : changes.cuts) {
      Loop2& route = segments_[cut.segment].route;
      std::vector<Point2>& gone = cut_out_[cut.segment];
      gone.insert(gone.end(), route.begin() + static_cast<std::ptrdiff_t>(cut.first),
                  route.begin() + static_cast<std::ptrdiff_t>(cut.last));
      route.erase(route.begin() + static_cast<std::ptrdiff_t>(cut.first),
                  route.begin() + static_cast<std::ptrdiff_t>(cut.last));
      changed_[cut.segment] = 1;
    }
  }

  Point2 resolve(const Point2& p) const {
    if (to_.empty()) return p;  // no merges, the common case: no hashing
    const auto it = to_.find(p);
    return it == to_.end() ? p : it->second;
  }

  // The pieces of every route; those of routes changed in the last round are fresh.
  void build_pieces() {
    pieces_.clear();
    for (std::uint32_t k = 0; k < segments_.size(); ++k) {
      const Segment& s = segments_[k];
      const bool fresh = changed_[k] != 0;
      Point2 from = resolve(s.from);
      std::uint32_t position = 0;
      auto add = [&](const Point2& to) {
        const std::uint32_t at = position++;
        if (to == from) return;
        const bool moved = from != s.from || to != s.to;
        // A point within its pixel of the piece lies in the piece's box grown by that
        // pixel, so its magnitude is at most a hair above the piece's own.
        double deviation = 0.0;
        if (moved) {
          deviation = std::min(
              std::max(distance_to_line(from, s.from, s.to), distance_to_line(to, s.from, s.to)),
              2.0 * std::max(snap_distance(from), snap_distance(to)));
        }
        const double margin =
            std::max(1.25 * std::max(snap_distance(from), snap_distance(to)), deviation);
        pieces_.push_back({from, to, k, at, margin, deviation, fresh});
        from = to;
      };
      for (const Point2& p : s.route) add(p);
      add(resolve(s.to));
    }
    std::fill(changed_.begin(), changed_.end(), 0);
  }

  // Merges vertices in each other's pixels. Each goes to a partner of its own merge,
  // never along a chain of them (a chain of vertices each within a pixel of the next
  // spans more than a pixel, and a vertex carried that far can cross an edge and turn the
  // boundary over): of two, the one with the wider pixel stays, then the least. Returns
  // whether any vertex moved.
  bool apply_merges(const std::vector<std::pair<Point2, Point2>>& merges) {
    bool moved = false;
    std::vector<std::pair<Point2, Point2>> pairs;
    for (const auto& [p, q] : merges) {
      const Point2 rp = resolve(p), rq = resolve(q);
      if (rp == rq || !within_snap_distance(rp, rq)) continue;
      pairs.emplace_back(std::min(rp, rq), std::max(rp, rq));
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [p, q] : pairs) {
      const Point2 rp = resolve(p), rq = resolve(q);
      if (rp == rq || !within_snap_distance(rp, rq)) continue;
      const double sp = snap_distance(rp), sq = snap_distance(rq);
      const bool keep_p = sp != sq ? sp > sq : rp < rq;
      const Point2 stay = keep_p ? rp : rq, go = keep_p ? rq : rp;
      // Whatever went to `go` goes on to `stay`, so resolve stays one lookup.
      for (auto& entry : to_) {
        if (entry.second == go) entry.second = stay;
      }
      to_[go] = stay;
      moved = true;
    }
    return moved;
  }

  // Puts each point into its piece, points into one piece in order along it.
  void insert(std::vector<Insertion>& insertions) {
    std::sort(insertions.begin(), insertions.end(), [](const Insertion& a, const Insertion& b) {
      return a.segment != b.segment ? a.segment < b.segment : a.position < b.position;
    });
    for (std::size_t g = 0; g < insertions.size();) {
      const std::uint32_t k = insertions[g].segment;
      std::size_t end = g;
      while (end < insertions.size() && insertions[end].segment == k) ++end;
      Segment& s = segments_[k];
      Loop2 route;
      route.reserve(s.route.size() + (end - g));
      std::size_t next = g;
      for (std::uint32_t position = 0; position <= s.route.size(); ++position) {
        const Point2 from = position == 0 ? resolve(s.from) : s.route[position - 1];
        const Point2 to = position == s.route.size() ? resolve(s.to) : s.route[position];
        const std::size_t first = next;
        while (next < end && insertions[next].position == position) ++next;
        const AlongSegment along(from, to);
        // Crossings of a whole input edge in the order of their exact points: rounded a
        // hair apart along a long edge, they can land in the opposite order, and the
        // pieces between them then cross the edges that made them. Farther apart than
        // their rounding, the rounded order is the exact one. An insertion sort: the two
        // orders together need not be a strict weak order, which std::sort requires.
        const bool whole = from == s.from && to == s.to;
        auto before = [&](const Insertion& a, const Insertion& b) {
          if (whole && a.crossing && b.crossing && a.at != b.at &&
              near_each_other(a.at, b.at, from, to)) {
            const Orientation side = orient2d_crossing(b.f0, b.f1, from, to, a.f0, a.f1);
            if (side != Orientation::kCollinear) return side == orient2d(b.f0, b.f1, from);
          }
          return along(a.at, b.at);
        };
        for (std::size_t m = first + 1; m < next; ++m) {
          for (std::size_t q = m; q > first && before(insertions[q], insertions[q - 1]); --q) {
            std::swap(insertions[q], insertions[q - 1]);
          }
        }
        for (std::size_t m = first; m < next; ++m) {
          const Point2& p = insertions[m].at;
          if ((route.empty() ? from : route.back()) != p && p != to) route.push_back(p);
        }
        if (position < s.route.size() && (route.empty() || route.back() != to)) route.push_back(to);
      }
      s.route = std::move(route);
      changed_[k] = 1;
      g = end;
    }
  }

  // Every route with its merged points replaced, repeats and its own ends dropped.
  void resolve_routes() {
    for (Segment& s : segments_) {
      const Point2 from = resolve(s.from), to = resolve(s.to);
      Loop2 route;
      route.reserve(s.route.size());
      for (const Point2& p : s.route) {
        const Point2 r = resolve(p);
        if (r == from || r == to || (!route.empty() && route.back() == r)) continue;
        route.push_back(r);
      }
      s.route = std::move(route);
    }
  }

  std::vector<Segment> segments_;
  std::vector<char> changed_;
  const bool hold_back_;
  std::vector<std::vector<Point2>> cut_out_;  // per segment, the points cuts took out of its route
  std::vector<Piece> pieces_;
  std::unordered_map<Point2, Point2, Point2Hash> to_;  // merged vertex -> the one it became
};

}  // namespace

SnapRoundingStats snap_round_in_rounds(const std::vector<Loop2> (&loops)[2], bool hold_back,
                                       std::vector<Loop2> (&snapped)[2]) {
  SnapRounder rounder(loops, hold_back);
  const SnapRoundingStats stats = rounder.run(loops);
  snapped[0] = loops[0];
  snapped[1] = loops[1];
  rounder.write_back(snapped);
  return stats;
}

}  // namespace shadowgen::clipper::detail
