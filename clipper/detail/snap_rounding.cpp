#include "snap_rounding.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>

#include "box_masks.h"
#include "clipper/clip.h"
#include "clipper/predicates.h"
#include "close_pairs.h"
#include "crossing.h"
#include "grid_snap.h"
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

// The common case decided without rounds: operands of a few edges that meet only where
// edges cross properly or where a vertex lies in an edge's way (on it, or off it within
// the vertex's pixel: an edge that a cut shared with an earlier clip, a T-junction), every
// other point well clear of every edge. The rounds would route each edge through the
// points found on it, in order along it, and then find nothing more: every other contact
// they look for (points in each other's pixels, a point in the way of an edge or of a
// piece moved by a rounded crossing or a vertex, pieces crossing anew) needs a point
// within a pixel plus a piece's deviation (two pixels at most) of an edge or of another
// point, and here every point lies more than kClearPixels of the widest pixel of the
// operands from each edge and point it is not routed through or on. Returns false,
// leaving the loops as they came, where that is not shown; snap_round then runs the
// rounds, which give the same loops wherever this gives any
// (SnapRound.TheShortcutGivesWhatTheRoundsGive).
constexpr std::size_t kShortcutEdges = 128;
constexpr double kClearPixels = 8.0;

// Whether p lies off the line through a and b by more than `reach`, in doubles with a
// generous bound (8u of the products' magnitudes) on the rounding of the determinant
// taken off.
bool off_line(const Point2& p, const Point2& a, const Point2& b, double reach) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double left = dx * (p.y - a.y), right = dy * (p.x - a.x);
  const double rounding = 0x1p-50 * (std::fabs(left) + std::fabs(right));
  return std::fabs(left - right) - rounding > 1.001 * reach * std::sqrt(dx * dx + dy * dy);
}

// Whether the rounds' first look routes the whole edge a-b through vertex v: v lies in
// the edge's box grown by its margin (ContactFinder's candidate test) and the edge passes
// through v's pixel. A line further from v than twice the pixel's half width misses the
// pixel (whose corners, rounded, lie within 1.1 half widths of v in each coordinate):
// that common answer is given in doubles, before the exact look at the four corners.
bool in_way(const Point2& v, const Point2& a, const Point2& b) {
  const double margin = 1.25 * std::max(snap_distance(a), snap_distance(b));
  return v.x >= std::min(a.x, b.x) - margin && v.x <= std::max(a.x, b.x) + margin &&
         v.y >= std::min(a.y, b.y) - margin && v.y <= std::max(a.y, b.y) + margin &&
         !off_line(v, a, b, 2.0 * snap_distance(v)) && within_snap_distance(v, a, b);
}

bool apart(const Point2& p, const Point2& q, double reach) {
  return std::fabs(p.x - q.x) > reach || std::fabs(p.y - q.y) > reach;
}

bool snap_round_separated(std::vector<Loop2> (&loops)[2], SnapRoundingStats* stats) {
  struct Edge {
    Point2 from, to;
    double xmin, xmax, ymin, ymax;  // the box, grown by the reach
    std::uint32_t next;             // the edge leaving `to`, in the same loop
  };
  // A point an edge is to be routed through.
  struct Through {
    std::uint32_t edge;
    Point2 at;
  };
  // Kept from call to call: a clip of small polygons would otherwise spend much of its
  // time allocating them.
  thread_local std::vector<Edge> edges;
  thread_local std::vector<Through> through;
  edges.clear();
  through.clear();
  double magnitude = 0.0;
  for (const auto& side : loops) {
    for (const Loop2& loop : side) {
      if (edges.size() + loop.size() > kShortcutEdges) return false;
      const auto first = static_cast<std::uint32_t>(edges.size());
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2& p = loop[i];
        const std::size_t next = i + 1 == loop.size() ? 0 : i + 1;
        edges.push_back({p, loop[next], 0, 0, 0, 0, first + static_cast<std::uint32_t>(next)});
        magnitude = std::max({magnitude, std::fabs(p.x), std::fabs(p.y)});
      }
    }
  }
  const double reach = kClearPixels * snap_distance({magnitude, magnitude});
  // At most kShortcutEdges edges: every pair is looked at, boxes first (a sweep's sorting
  // cost more than it saved at these sizes). The vertices and boxes are also laid out
  // coordinate by coordinate, so that a box is tested against all of them at once.
  const std::size_t n = edges.size();
  MaskLane vx, vy, bx0, bx1, by0, by1;
  for (std::size_t k = 0; k < n; ++k) {
    Edge& e = edges[k];
    e.xmin = std::min(e.from.x, e.to.x) - reach;
    e.xmax = std::max(e.from.x, e.to.x) + reach;
    e.ymin = std::min(e.from.y, e.to.y) - reach;
    e.ymax = std::max(e.from.y, e.to.y) + reach;
    vx[k] = e.from.x;
    vy[k] = e.from.y;
    bx0[k] = e.xmin;
    bx1[k] = e.xmax;
    by0[k] = e.ymin;
    by1[k] = e.ymax;
  }
  for (MaskLane* lane : {&vx, &vy, &bx0, &bx1, &by0, &by1}) lane->pad(n);
  static_assert(kShortcutEdges <= MaskLane::kCapacity, "a lane for every edge");
  std::size_t splits = 0;
  // Vertices: apart from one another, and each clear of every edge or in its way between
  // its ends (then found there by both edges the vertex ends). Every vertex starts an
  // edge, and a point within the reach of it lies in that edge's grown box. An edge's
  // own ends are not looked at from it: its end is the next edge's start, whose test
  // against this edge's start (in the next edge's box when they are not apart) tells.
  for (std::uint32_t m = 0; m < n; ++m) {
    const Edge& e = edges[m];
    const bool clear =
        each_box_meeting(vx, vx, vy, vy, 0, n, e.xmin, e.xmax, e.ymin, e.ymax, [&](std::size_t k) {
          if (k == m || k == e.next) return true;
          const Point2& v = edges[k].from;
          if (v == e.from) return true;
          if (!apart(v, e.from, reach)) return false;
          if (v == e.to || off_line(v, e.from, e.to, reach)) return true;
          if (!in_way(v, e.from, e.to) || !apart(v, e.to, reach)) return false;
          through.push_back({m, v});
          splits += 2;
          return true;
        });
    if (!clear) return false;
  }
  // Proper crossings, rounded: apart from every vertex and clear of every edge but their
  // own two. Each pair once: the boxes after this one's, but for the next edge's, which
  // shares an end with it.
  std::size_t crossings = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Edge& a = edges[i];
    const bool clear = each_box_meeting(
        bx0, bx1, by0, by1, i + 1, n, a.xmin, a.xmax, a.ymin, a.ymax, [&](std::size_t k) {
          if (k == a.next) return true;
          const auto j = static_cast<std::uint32_t>(k);
          const Edge& b = edges[j];
          if (a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to) return true;
          if (!properly_cross(a.from, a.to, b.from, b.to)) return true;
          // A vertex of one in the other's way (a hair across it): routed through, not
          // crossed.
          if (in_way(a.from, b.from, b.to) || in_way(a.to, b.from, b.to) ||
              in_way(b.from, a.from, a.to) || in_way(b.to, a.from, a.to)) {
            return true;
          }
          const Point2 at = crossing_point(a.from, a.to, b.from, b.to);
          // The edges whose grown boxes hold the crossing.
          const bool at_clear = each_box_meeting(
              bx0, bx1, by0, by1, 0, n, at.x, at.x, at.y, at.y, [&](std::size_t m) {
                const Edge& e = edges[m];
                if (!apart(at, e.from, reach)) return false;
                return m == i || m == j || off_line(at, e.from, e.to, reach);
              });
          if (!at_clear) return false;
          through.push_back({i, at});
          through.push_back({j, at});
          ++crossings;
          splits += 2;
          return true;
        });
    if (!clear) return false;
  }
  if (!through.empty() && snap_round_limit() < 1) return false;
  std::sort(through.begin(), through.end(), [](const Through& a, const Through& b) {
    if (a.edge != b.edge) return a.edge < b.edge;
    return AlongSegment(edges[a.edge].from, edges[a.edge].to)(a.at, b.at);
  });
  std::size_t k = 0, next = 0;
  for (auto& side : loops) {
    for (Loop2& loop : side) {
      LoopOfRoutes out(loop.size() + through.size());
      for (std::size_t i = 0; i < loop.size(); ++i, ++k) {
        out.add(edges[k].from);
        for (; next < through.size() && through[next].edge == k; ++next) out.add(through[next].at);
      }
      loop = out.take();
    }
  }
  if (stats != nullptr) {
    *stats = {};
    stats->crossings = crossings;
    stats->splits = splits;
    stats->rounds = through.empty() ? 0 : 1;
    stats->separated = true;
  }
  return true;
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
    SnapRounder rounder(loops, hold_back);
    local = rounder.run(loops);
    if (stats != nullptr) *stats = local;
    std::vector<Loop2> snapped[2] = {loops[0], loops[1]};
    rounder.write_back(snapped);
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
