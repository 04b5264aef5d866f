#include "snap_rounding.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "clipper/clip.h"
#include "clipper/predicates.h"
#include "close_pairs.h"
#include "crossing.h"
#include "snap.h"

namespace shadowgen::clipper::detail {
namespace {

// Rounds of changes after which the snapping stops. A round looks only at what the
// previous one changed; a second round finds something on near-degenerate input only, a
// third was seen on adversarial input alone. The bound keeps the cost finite whatever the
// input: some inputs (a route that comes back to a point it passes, on self-crossing
// boundaries) cut and put back the same point round after round, and are left as the
// limit finds them, provided their edges meet only at vertices (noded, below).
constexpr int kMaxRounds = 17;

// The limit in force: kMaxRounds but while a SnapRoundLimitForTesting lives (clip.h).
std::atomic<int> round_limit{kMaxRounds};

using PointSet = std::unordered_set<Point2, Point2Hash>;

double distance(const Point2& p, const Point2& q) { return std::hypot(q.x - p.x, q.y - p.y); }

bool properly_cross(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1) {
  const Orientation oa0 = orient2d(b0, b1, a0);
  const Orientation oa1 = orient2d(b0, b1, a1);
  if (oa0 == Orientation::kCollinear || oa1 == Orientation::kCollinear || oa0 == oa1) return false;
  const Orientation ob0 = orient2d(a0, a1, b0);
  const Orientation ob1 = orient2d(a0, a1, b1);
  return ob0 != Orientation::kCollinear && ob1 != Orientation::kCollinear && ob0 != ob1;
}

// Whether v lies strictly between the ends of a0-a1 by projection and within d of it.
bool within_distance(const Point2& v, const Point2& a0, const Point2& a1, double d) {
  if (!projects_inside(v, a0, a1)) return false;
  const double dx = a1.x - a0.x, dy = a1.y - a0.y;
  return std::fabs(orient2d_value(a0, a1, v)) <= d * std::sqrt(dx * dx + dy * dy);
}

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

// An input edge, and the points it is routed through.
struct Segment {
  Point2 from, to;
  Loop2 route;  // interior points, in order from `from` to `to`
};

// A piece of a route: the edge between two consecutive points of it.
struct Piece {
  Point2 from, to;
  std::uint32_t segment;
  std::uint32_t position;  // it ends at route[position], or at the segment's end
  double margin;           // how far a point meeting it can lie from its box
  double deviation;        // how far it may lie from its segment's line (at its ends, at most)
  bool fresh;              // made or moved in the last round
};

bool in_box(const Point2& p, const Piece& e) {
  return p.x >= std::min(e.from.x, e.to.x) - e.margin &&
         p.x <= std::max(e.from.x, e.to.x) + e.margin &&
         p.y >= std::min(e.from.y, e.to.y) - e.margin &&
         p.y <= std::max(e.from.y, e.to.y) + e.margin;
}

// What one round finds: points each segment must be routed through, and vertices to
// merge.
// A point some piece must pass through. A crossing of two pieces that are whole input
// edges keeps the other one, which orders it exactly among others on the same edge.
struct Through {
  std::uint32_t piece;
  Point2 at;
  bool crossing = false;
  Point2 f0{}, f1{};
};

struct Contacts {
  std::vector<Through> through;
  std::vector<std::pair<Point2, Point2>> merges;
  std::size_t crossings = 0;
};

class Finder {
 public:
  Finder(const std::vector<Piece>& pieces, const std::vector<Segment>& segments, Contacts& found)
      : pieces_(pieces), segments_(segments), found_(found) {}

  void find(std::size_t i, std::size_t j) {
    const Piece& a = pieces_[i];
    const Piece& b = pieces_[j];
    // Vertices in each other's pixels become one: first, as the other contacts of the
    // two pieces change with it. (Each asked, none skipped: every merge is recorded.)
    const bool m0 = merge(a.from, b.from), m1 = merge(a.from, b.to);
    const bool m2 = merge(a.to, b.from), m3 = merge(a.to, b.to);
    if (m0 || m1 || m2 || m3) return;
    // A vertex of one in the other's way: the other's segment is routed through it. The
    // two then share that vertex and cannot cross: no crossing is made, which would only
    // be rounded a hair from it (two nearly parallel edges, crossed again and again by
    // the rounding of each new crossing, would never settle).
    const bool s0 = snap(a.from, j), s1 = snap(a.to, j), s2 = snap(b.from, i), s3 = snap(b.to, i);
    if (s0 || s1 || s2 || s3) return;
    if (a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to) return;
    if (properly_cross(a.from, a.to, b.from, b.to)) cross(i, j);
  }

 private:
  bool merge(const Point2& p, const Point2& q) {
    if (!within_snap_distance(p, q)) return false;
    found_.merges.emplace_back(p, q);
    return true;
  }

  // Whether v lies in piece e's way: e passes through v's pixel (exactly through v
  // included), or v lies between e and its segment's line, nearer e than e moved from it
  // (e moved when routed through a vertex off its segment, by up to that vertex's pixel,
  // which far from the origin is wider than the pixels of vertices it passes nearer the
  // origin; such a vertex would otherwise end on the wrong side of e, and a needle of
  // the input turn over there).
  bool snap(const Point2& v, std::size_t piece) {
    const Piece& e = pieces_[piece];
    if (!in_box(v, e)) return false;
    const Segment& s = segments_[e.segment];
    const bool in_way = within_snap_distance(v, e.from, e.to) ||
                        (e.deviation > 0.0 && within_distance(v, e.from, e.to, e.deviation) &&
                         between_piece_and_line(v, e, s));
    if (!in_way) return false;
    found_.through.push_back({static_cast<std::uint32_t>(piece), v});
    return true;
  }

  // Whether v lies off the segment's line on the side the piece moved to, and on the
  // line's side of the piece: where the piece's move could have carried it across v.
  // Vertices beyond the piece are not routed in, or each round would carry the piece a
  // pixel further out.
  static bool between_piece_and_line(const Point2& v, const Piece& e, const Segment& s) {
    const Orientation moved = orient2d(s.from, s.to, e.from) != Orientation::kCollinear
                                  ? orient2d(s.from, s.to, e.from)
                                  : orient2d(s.from, s.to, e.to);
    const Orientation side = orient2d(s.from, s.to, v);
    if (side == Orientation::kCollinear || side != moved) return false;
    // The line lies on the side of the piece where the segment's ends off it lie.
    Orientation line = orient2d(e.from, e.to, s.from);
    if (line == Orientation::kCollinear) line = orient2d(e.from, e.to, s.to);
    const Orientation of_v = orient2d(e.from, e.to, v);
    return line == Orientation::kCollinear || of_v == Orientation::kCollinear || of_v == line;
  }

  // The rounded crossing of two properly crossing pieces routes both segments through
  // it. Where the segments themselves cross, near the pieces, their crossing is taken: it
  // lies within rounding of both input lines, which the pieces' crossing need not. A
  // crossing in the pixel of an endpoint of the pieces is that endpoint (the nearest,
  // then the least): rounded there, nothing tells the two apart.
  void cross(std::size_t i, std::size_t j) {
    const Piece& a = pieces_[i];
    const Piece& b = pieces_[j];
    const Segment& sa = segments_[a.segment];
    const Segment& sb = segments_[b.segment];
    Point2 p = crossing_point(a.from, a.to, b.from, b.to);
    if (a.deviation > 0.0 || b.deviation > 0.0) {
      if (properly_cross(sa.from, sa.to, sb.from, sb.to)) {
        // Unless both segments already pass through it: then the pieces cross somewhere
        // else, where a piece moved across the other, and that crossing is the one to make.
        const Point2 q = crossing_point(sa.from, sa.to, sb.from, sb.to);
        if (in_box(q, a) && in_box(q, b) && !(passes_through(sa, q) && passes_through(sb, q))) {
          p = q;
        }
      }
    }
    const Point2* nearest = nullptr;
    double nearest_distance = INFINITY;
    for (const Point2* end : {&a.from, &a.to, &b.from, &b.to}) {
      if (*end != p && !within_snap_distance(p, *end)) continue;
      const double d = distance(p, *end);
      if (d < nearest_distance || (d == nearest_distance && *end < *nearest)) {
        nearest = end;
        nearest_distance = d;
      }
    }
    if (nearest != nullptr) {
      p = *nearest;
    } else {
      ++found_.crossings;
    }
    // Whole input edges on both sides: the exact crossing is known by its two edges.
    const bool whole = a.from == sa.from && a.to == sa.to && b.from == sb.from && b.to == sb.to;
    found_.through.push_back({static_cast<std::uint32_t>(i), p, whole, b.from, b.to});
    found_.through.push_back({static_cast<std::uint32_t>(j), p, whole, a.from, a.to});
  }

  // Whether p is an end of the segment or on its route (as the route is before merging).
  static bool passes_through(const Segment& s, const Point2& p) {
    return p == s.from || p == s.to ||
           std::find(s.route.begin(), s.route.end(), p) != s.route.end();
  }

  const std::vector<Piece>& pieces_;
  const std::vector<Segment>& segments_;
  Contacts& found_;
};

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
  };

 public:
  explicit SnapRounder(const std::vector<Loop2> (&loops)[2]) {
    for (int side = 0; side < 2; ++side) {
      for (const Loop2& loop : loops[side]) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
          segments_.push_back({loop[i], loop[i + 1 == loop.size() ? 0 : i + 1], {}});
        }
      }
    }
    changed_.assign(segments_.size(), 1);
  }

  SnapRoundingStats run() {
    SnapRoundingStats stats;
    const int limit = round_limit.load(std::memory_order_relaxed);
    for (int round = 0;; ++round) {
      build_pieces();
      Contacts found;
      Finder finder(pieces_, segments_, found);
      // Pairs of unchanged pieces were looked at when the younger of them was made.
      for_each_close_pair(
          pieces_, [this](std::size_t i) { return pieces_[i].margin; },
          [this](std::size_t i) { return pieces_[i].fresh; },
          [&finder](std::size_t i, std::size_t j) { finder.find(i, j); });
      if (found.through.empty() && found.merges.empty()) break;
      if (round == limit) {
        // Stopped with this round's changes not made: whether the edges meet only at
        // vertices is then checked exactly (snap_round).
        stats.converged = false;
        break;
      }
      stats.crossings += found.crossings;
      const bool merged = apply_merges(found.merges);
      Changes changes = plan(found.through);
      const bool added = !changes.insertions.empty() || !changes.cuts.empty();
      apply(changes);
      if (!merged && !added) break;
      ++stats.rounds;
      stats.splits += changes.insertions.size();
      if (merged) {
        std::fill(changed_.begin(), changed_.end(), 1);
        resolve_routes();
      }
    }
    return stats;
  }

  // The loops, each edge replaced by its route.
  void write_back(std::vector<Loop2> (&loops)[2]) const {
    std::size_t k = 0;
    for (int side = 0; side < 2; ++side) {
      for (Loop2& loop : loops[side]) {
        const std::size_t n = loop.size();
        Loop2 out;
        out.reserve(n);
        auto push = [&out](const Point2& p) {
          if (out.empty() || out.back() != p) out.push_back(p);
        };
        for (std::size_t i = 0; i < n; ++i, ++k) {
          const Segment& s = segments_[k];
          push(resolve(s.from));
          for (const Point2& p : s.route) push(p);
        }
        while (out.size() > 1 && out.back() == out.front()) out.pop_back();
        if (out.size() < 2) out.clear();  // merged into a single point: bounds nothing
        loop = std::move(out);
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
  std::vector<Piece> pieces_;
  std::unordered_map<Point2, Point2, Point2Hash> to_;  // merged vertex -> the one it became
};

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

// Whether the loops' edges all meet only at vertices: the plane graph the overlay needs,
// which a round limit can leave the snapping short of.
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

}  // namespace

void snap_round(std::vector<Loop2> (&loops)[2], SnapRoundingStats* stats) {
  SnapRounder rounder(loops);
  const SnapRoundingStats local = rounder.run();
  if (stats != nullptr) *stats = local;
  if (local.converged) {
    rounder.write_back(loops);
    return;
  }
  std::vector<Loop2> snapped[2] = {loops[0], loops[1]};
  rounder.write_back(snapped);
  if (!noded(snapped)) {
    std::size_t edges = 0;
    for (const auto& side : loops) {
      for (const Loop2& loop : side) edges += loop.size();
    }
    throw SnapRoundingError("snap rounding of " + std::to_string(edges) +
                            " edges did not settle within " + std::to_string(local.rounds) +
                            " rounds: edges still meet elsewhere than at common vertices");
  }
  loops[0] = std::move(snapped[0]);
  loops[1] = std::move(snapped[1]);
}

}  // namespace shadowgen::clipper::detail

namespace shadowgen::clipper {

// The test hook of clip.h, here beside the limit it sets.
SnapRoundLimitForTesting::SnapRoundLimitForTesting(int rounds)
    : previous_(detail::round_limit.exchange(std::max(rounds, 0))) {}

SnapRoundLimitForTesting::~SnapRoundLimitForTesting() { detail::round_limit.store(previous_); }

}  // namespace shadowgen::clipper
