#include "loop_validation.h"

#include <algorithm>
#include <compare>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <utility>

#include "clipper/normalize.h"
#include "clipper/predicates.h"
#include "clipper/segment_contact.h"

namespace shadowgen::detail {

namespace {

using clipper::orient2d;
using clipper::Orientation;
using clipper::Point2;

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

int sign(Orientation o) { return static_cast<int>(o); }

// A loop with consecutive repeated vertices removed, remembering where each kept vertex
// was in the given loop (for messages).
struct CleanLoop {
  std::vector<Point2> points;
  std::vector<std::size_t> original;
};

CleanLoop clean(const clipper::Loop2& loop) {
  CleanLoop c;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (!c.points.empty() && loop[i] == c.points.back()) continue;
    c.points.push_back(loop[i]);
    c.original.push_back(i);
  }
  while (c.points.size() > 1 && c.points.back() == c.points.front()) {
    c.points.pop_back();
    c.original.pop_back();
  }
  return c;
}

struct Box {
  double xmin, xmax, ymin, ymax;
  bool contains(const Box& b) const {
    return xmin <= b.xmin && b.xmax <= xmax && ymin <= b.ymin && b.ymax <= ymax;
  }
};

struct Edge {
  Point2 a, b;
  Box box;
  std::uint32_t loop;
  std::uint32_t index;  // edge index = index of its first vertex in the clean loop
};

// Where a loop passes through a point: the points before and after it along the loop.
struct Corner {
  Point2 prev, at, next;
};

// Strictly to the left of the path prev -> at -> next, near `at`.
bool left_of(const Corner& c, const Point2& w) {
  const int turn = sign(orient2d(c.prev, c.at, c.next));
  const bool left_of_in = orient2d(c.prev, c.at, w) == Orientation::kCounterClockwise;
  const bool left_of_out = orient2d(c.at, c.next, w) == Orientation::kCounterClockwise;
  if (turn > 0) return left_of_in && left_of_out;
  return left_of_in || left_of_out;  // reflex, or straight (then both agree)
}

// Whether two passages through one point cross there: the directions in and out of one
// lie on both sides of the other's path. Their directions must all differ.
bool cross(const Corner& a, const Corner& b) {
  return left_of(a, b.prev) != left_of(a, b.next) || left_of(b, a.prev) != left_of(b, a.next);
}

// Crossing-number test, exact; `p` must not lie on the loop.
bool inside_loop(const std::vector<Point2>& loop, const Point2& p) {
  bool inside = false;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[(i + 1) % n];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    // The edge crosses the horizontal line through p; count it when it does so right of p.
    const Orientation o = orient2d(a, b, p);
    if (b.y > a.y ? o == Orientation::kCounterClockwise : o == Orientation::kClockwise) {
      inside = !inside;
    }
  }
  return inside;
}

// What the directed edge a -> b adds to the winding number around x, which is not on it.
int winding(const Point2& a, const Point2& b, const Point2& x) {
  if (a.y <= x.y) {
    if (b.y > x.y && orient2d(a, b, x) == Orientation::kCounterClockwise) return 1;
  } else if (b.y <= x.y && orient2d(a, b, x) == Orientation::kClockwise) {
    return -1;
  }
  return 0;
}

// Directions from p, counter-clockwise from +x, exactly; q1 and q2 must not lie in the
// same direction.
bool angle_less(const Point2& p, const Point2& q1, const Point2& q2) {
  auto upper = [&p](const Point2& q) { return q.y > p.y || (q.y == p.y && q.x > p.x); };
  if (upper(q1) != upper(q2)) return upper(q1);
  return orient2d(p, q1, q2) == Orientation::kCounterClockwise;
}

// A direction from a point along a loop: to the vertex before (into the point) or after.
struct Ray {
  Point2 to;
  bool out;
};

// A loop passes a point at one of its vertices, or inside one of its edges (touching
// another loop there).
struct Passage {
  std::uint32_t loop;
  std::uint32_t index;  // the vertex, or with inside_edge the edge, in the clean loop
  bool inside_edge;
  friend auto operator<=>(const Passage&, const Passage&) = default;
};

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::size_t> parent_;
};

class Checker {
 public:
  Checker(std::span<const clipper::Loop2> loops, std::span<const std::string> names)
      : names_(names) {
    loops_.reserve(loops.size());
    for (const clipper::Loop2& loop : loops) loops_.push_back(clean(loop));
    bridge_partner_.resize(loops_.size());
    pinched_.resize(loops_.size(), false);
    pieces_.resize(loops_.size());
  }

  LoopCheck run() {
    LoopCheck result;
    result.problem = check();
    if (!result.problem) result.counter_clockwise = std::move(ccw_);
    return result;
  }

 private:
  // A pinched or bridged loop with its bridges taken out: after each edge into a point,
  // the edge out of it that the loop takes next, jumping over bridges.
  struct Pieces {
    std::vector<std::uint32_t> next_edge;                   // by edge; kNone for bridges
    std::map<Point2, std::vector<std::uint32_t>> edges_in;  // edges ending at each point
  };

  std::optional<std::string> check() {
    for (std::size_t l = 0; l < loops_.size(); ++l) {
      if (loops_[l].points.size() < 3) return names_[l] + " has no area in the face's plane";
    }
    if (auto problem = sweep_edges()) return problem;
    add_vertex_passages();
    for (const auto& [at, passages] : touches_) {
      if (auto problem = check_crossings(at, passages)) return problem;
    }
    ccw_.resize(loops_.size());
    for (std::uint32_t l = 0; l < loops_.size(); ++l) {
      if (bridge_partner_[l].empty() && !pinched_[l]) {
        ccw_[l] = clipper::is_counter_clockwise(loops_[l].points);
      } else if (auto problem = check_pieces(l)) {
        return problem;
      }
    }
    for (const auto& [at, passages] : touches_) {
      if (auto problem = check_sides(at, passages)) return problem;
    }
    return check_containment();
  }

  std::string vertex_name(std::uint32_t loop, std::size_t clean_index) const {
    const CleanLoop& l = loops_[loop];
    return std::to_string(l.original[clean_index % l.points.size()]);
  }
  std::string edge_name(const Edge& e) const {
    return vertex_name(e.loop, e.index) + "-" + vertex_name(e.loop, e.index + 1);
  }
  bool is_bridge(std::uint32_t loop, std::uint32_t edge) const {
    return !bridge_partner_[loop].empty() && bridge_partner_[loop][edge] != kNone;
  }

  std::optional<std::string> sweep_edges() {
    std::vector<Edge> edges;
    for (std::uint32_t l = 0; l < loops_.size(); ++l) {
      const std::vector<Point2>& p = loops_[l].points;
      for (std::uint32_t i = 0; i < p.size(); ++i) {
        const Point2& a = p[i];
        const Point2& b = p[(i + 1) % p.size()];
        edges.push_back(
            {a, b,
             Box{std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)}, l,
             i});
      }
    }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& e, const Edge& f) { return e.box.xmin < f.box.xmin; });
    std::vector<std::size_t> active;
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const Edge& e = edges[k];
      // One pass drops the edges the sweep has left behind and tests the others.
      std::size_t kept = 0;
      for (std::size_t i = 0; i < active.size(); ++i) {
        const Edge& f = edges[active[i]];
        if (f.box.xmax < e.box.xmin) continue;
        active[kept++] = active[i];
        if (f.box.ymax < e.box.ymin || f.box.ymin > e.box.ymax) continue;
        if (auto problem = check_pair(f, e)) return problem;
      }
      active.resize(kept);
      active.push_back(k);
    }
    return std::nullopt;
  }

  std::optional<std::string> check_pair(const Edge& e0, const Edge& f0) {
    const clipper::SegmentContact m = clipper::segment_contact(e0.a, e0.b, f0.a, f0.b);
    if (m.contact == clipper::Contact::kNone) return std::nullopt;
    // Lower loop first, so the outer loop is named first.
    const bool swap = f0.loop < e0.loop || (f0.loop == e0.loop && f0.index < e0.index);
    const Edge& e = swap ? f0 : e0;
    const Edge& f = swap ? e0 : f0;
    auto ends_at = [](const Edge& g, const Point2& x) { return g.a == x || g.b == x; };
    if (e.loop == f.loop) {
      const std::size_t n = loops_[e.loop].points.size();
      const bool adjacent = (e.index + 1) % n == f.index || (f.index + 1) % n == e.index;
      if (adjacent) {
        if (m.contact != clipper::Contact::kOverlap) return std::nullopt;  // their shared vertex
        const std::size_t shared = (e.index + 1) % n == f.index ? f.index : e.index;
        return names_[e.loop] + " doubles back on itself at vertex " + vertex_name(e.loop, shared);
      }
      // The loop passes a vertex again (pinched): whether it crosses over there is decided
      // with all its passages through that point.
      if (m.contact == clipper::Contact::kTouch && ends_at(e, m.at) && ends_at(f, m.at)) {
        touches_[m.at];
        pinched_[e.loop] = true;
        return std::nullopt;
      }
      // The same edge run once each way: a bridge.
      if (m.contact == clipper::Contact::kOverlap && e.a == f.b && e.b == f.a) {
        std::vector<std::uint32_t>& partner = bridge_partner_[e.loop];
        if (partner.empty()) partner.assign(n, kNone);
        partner[e.index] = f.index;
        partner[f.index] = e.index;
        return std::nullopt;
      }
      return names_[e.loop] + " intersects itself (edges " + edge_name(e) + " and " + edge_name(f) +
             " meet)";
    }
    const std::string edges = "(edge " + edge_name(e) + " of " + names_[e.loop] + ", edge " +
                              edge_name(f) + " of " + names_[f.loop] + ")";
    if (m.contact == clipper::Contact::kCross) {
      return names_[f.loop] + " crosses " + names_[e.loop] + " " + edges;
    }
    if (m.contact == clipper::Contact::kOverlap) {
      return names_[f.loop] + " runs along " + names_[e.loop] + " " + edges +
             "; loops may touch only at points";
    }
    std::vector<Passage>& passages = touches_[m.at];
    if (!ends_at(e, m.at)) passages.push_back({e.loop, e.index, true});
    if (!ends_at(f, m.at)) passages.push_back({f.loop, f.index, true});
    return std::nullopt;
  }

  // Every vertex at a point where loops touch, or where one passes again, is a passage.
  void add_vertex_passages() {
    if (touches_.empty()) return;
    for (std::uint32_t l = 0; l < loops_.size(); ++l) {
      const std::vector<Point2>& p = loops_[l].points;
      for (std::uint32_t i = 0; i < p.size(); ++i) {
        if (const auto it = touches_.find(p[i]); it != touches_.end()) {
          it->second.push_back({l, i, false});
        }
      }
    }
    for (auto& [at, passages] : touches_) {
      std::sort(passages.begin(), passages.end());
      passages.erase(std::unique(passages.begin(), passages.end()), passages.end());
    }
  }

  Corner corner(const Passage& s, const Point2& at) const {
    const std::vector<Point2>& p = loops_[s.loop].points;
    const std::size_t n = p.size();
    if (s.inside_edge) return {p[s.index], at, p[(s.index + 1) % n]};
    return {p[(s.index + n - 1) % n], at, p[(s.index + 1) % n]};
  }

  std::string point_name(const std::vector<Passage>& passages) const {
    for (const Passage& s : passages) {
      if (!s.inside_edge) return "vertex " + vertex_name(s.loop, s.index) + " of " + names_[s.loop];
    }
    return "a point";  // not reached: every touch is at a vertex of one of the loops
  }

  // No two passages through a point may cross there, whichever loops they belong to. Two
  // that share a direction are the two runs of a bridge, which go apart without crossing.
  std::optional<std::string> check_crossings(const Point2& at,
                                             const std::vector<Passage>& passages) const {
    // Bridges may run on from one to the next (a path run both ways), but not branch: at a
    // point where a passage comes in and goes out along bridges, the only other passage is
    // the same path run back. (Branching bridges can wind the right way round everywhere
    // and still be impossible to pull apart without crossing.)
    for (const Passage& s : passages) {
      const std::size_t n = loops_[s.loop].points.size();
      if (s.inside_edge || !is_bridge(s.loop, static_cast<std::uint32_t>((s.index + n - 1) % n)) ||
          !is_bridge(s.loop, s.index)) {
        continue;
      }
      const Corner c = corner(s, at);
      const bool path = passages.size() == 2 &&
                        std::all_of(passages.begin(), passages.end(), [&](const Passage& t) {
                          const Corner d = corner(t, at);
                          return t.loop == s.loop && ((d.prev == c.prev && d.next == c.next) ||
                                                      (d.prev == c.next && d.next == c.prev));
                        });
      if (!path) {
        return names_[s.loop] + " runs both ways along edges that branch at vertex " +
               vertex_name(s.loop, s.index) +
               "; only a path may be run both ways (a bridge to an inner boundary)";
      }
    }
    for (std::size_t i = 0; i < passages.size(); ++i) {
      const Corner a = corner(passages[i], at);
      for (std::size_t j = i + 1; j < passages.size(); ++j) {
        const Corner b = corner(passages[j], at);
        if (a.prev == b.prev || a.prev == b.next || a.next == b.prev || a.next == b.next) continue;
        if (!cross(a, b)) continue;
        const Passage& s = passages[i];
        const Passage& t = passages[j];
        if (s.loop == t.loop) {
          return names_[s.loop] + " intersects itself: it crosses over at vertex " +
                 vertex_name(s.loop, s.index) + ", which it passes again as vertex " +
                 vertex_name(t.loop, t.index);
        }
        return names_[t.loop] + " crosses " + names_[s.loop] + " at " + point_name(passages);
      }
    }
    return std::nullopt;
  }

  // A pinched or bridged loop: takes the bridges out, checks that the pieces left bound
  // each point's neighbourhood once at most, and finds the loop's orientation.
  std::optional<std::string> check_pieces(std::uint32_t l) {
    const std::vector<Point2>& p = loops_[l].points;
    const auto n = static_cast<std::uint32_t>(p.size());
    Pieces& pieces = pieces_[l];
    pieces.next_edge.assign(n, kNone);
    for (std::uint32_t k = 0; k < n; ++k) {
      if (is_bridge(l, k)) continue;
      std::uint32_t j = (k + 1) % n;
      for (std::uint32_t steps = 0; is_bridge(l, j); ++steps) {
        if (steps > n) return names_[l] + " has no area in the face's plane";
        j = (bridge_partner_[l][j] + 1) % n;
      }
      pieces.next_edge[k] = j;
      pieces.edges_in[p[(k + 1) % n]].push_back(k);
    }
    if (pieces.edges_in.empty()) {
      return names_[l] + " has no area in the face's plane: it runs along every edge both ways";
    }

    // The directions in and out of each point, counter-clockwise: they must alternate, or
    // the winding number would step twice the same way around the point.
    auto rays_at = [&](const std::vector<std::uint32_t>& in) {
      std::vector<Ray> rays;
      for (const std::uint32_t k : in) {
        rays.push_back({p[k], false});
        rays.push_back({p[(pieces.next_edge[k] + 1) % n], true});
      }
      return rays;
    };
    for (const auto& [at, in] : pieces.edges_in) {
      if (in.size() < 2) continue;
      std::vector<Ray> rays = rays_at(in);
      std::sort(rays.begin(), rays.end(),
                [&at](const Ray& a, const Ray& b) { return angle_less(at, a.to, b.to); });
      for (std::size_t i = 0; i < rays.size(); ++i) {
        if (rays[i].out == rays[(i + 1) % rays.size()].out) {
          return names_[l] + " overlaps itself at vertex " + vertex_name(l, (in[0] + 1) % n) +
                 ": around it, it covers an area twice or runs the wrong way round";
        }
      }
    }

    // The pieces: the bridge-free edges joined at shared points.
    std::map<Point2, std::size_t> node;
    for (const auto& [at, in] : pieces.edges_in) node.emplace(at, node.size());
    DisjointSets sets(node.size());
    for (std::uint32_t k = 0; k < n; ++k) {
      if (!is_bridge(l, k)) sets.join(node.at(p[k]), node.at(p[(k + 1) % n]));
    }
    // Alone, a piece winds 0 around the points outside it and, since its directions
    // alternate, the same +1 or -1 beside all its edges on their other side: +1 when, at
    // its lowest point (x, then y), where all its directions point into one half-plane, the
    // first of them counter-clockwise from straight down is an edge out of the point.
    // Nodes in map order meet each piece first at its lowest point.
    std::map<std::size_t, std::pair<Point2, int>> lowest;  // by piece: point, inner winding
    for (const auto& [at, in] : pieces.edges_in) {
      const std::size_t piece = sets.find(node.at(at));
      if (lowest.count(piece) != 0) continue;
      const std::vector<Ray> rays = rays_at(in);
      const Ray* first = &rays[0];
      for (const Ray& r : rays) {
        if (orient2d(at, r.to, first->to) == Orientation::kCounterClockwise) first = &r;
      }
      lowest.emplace(piece, std::pair<Point2, int>(at, first->out ? 1 : -1));
    }
    // Together they wind 0 or +-1 everywhere when, beside the edges of every piece, the
    // winding number takes the two values it takes beside the piece through the loop's
    // lowest point, which no other piece surrounds: the others must wind 0 around a piece
    // that runs the loop's way round, and the loop's +-1 around one that runs the other
    // way (an inner boundary of the region).
    const std::size_t first_piece = sets.find(node.begin()->second);
    const int base = lowest.at(first_piece).second > 0 ? 0 : -1;
    for (const auto& [piece, low] : lowest) {
      if (piece == first_piece) continue;
      int around = low.second > 0 ? 0 : -1;
      for (std::uint32_t k = 0; k < n; ++k) {
        if (is_bridge(l, k) || sets.find(node.at(p[k])) == piece) continue;
        around += winding(p[k], p[(k + 1) % n], low.first);
      }
      if (around != base) {
        const std::uint32_t k = pieces.edges_in.at(low.first)[0];
        return names_[l] + " overlaps itself: the part of it through vertex " +
               vertex_name(l, (k + 1) % n) +
               " lies in its own region and runs the same way round, or outside it and the "
               "other way";
      }
    }
    ccw_[l] = base == 0;
    return std::nullopt;
  }

  // Two loops that touch at a point must lie on the proper sides of each other there: a
  // hole inside the outer loop, two holes outside each other. Near the point, a loop's
  // side is told by its directions in and out of it (bridges taken out), in angular order:
  // they alternate, and a direction w lies in the loop's region when the loop's direction
  // next clockwise from w is an edge out of the point (counter-clockwise loops, region to
  // the left) or into it (clockwise ones).
  std::optional<std::string> check_sides(const Point2& at, const std::vector<Passage>& passages) {
    std::map<std::uint32_t, std::vector<Ray>> sides;
    std::set<std::uint32_t> pieces_added;
    for (const Passage& s : passages) {
      std::vector<Ray>& rays = sides[s.loop];
      auto add = [&rays](const Corner& c) {
        rays.push_back({c.prev, false});
        rays.push_back({c.next, true});
      };
      if (bridge_partner_[s.loop].empty()) {
        add(corner(s, at));
      } else if (s.inside_edge) {
        if (!is_bridge(s.loop, s.index)) add(corner(s, at));
      } else if (pieces_added.insert(s.loop).second) {
        const Pieces& pieces = pieces_[s.loop];
        const std::vector<Point2>& p = loops_[s.loop].points;
        if (const auto it = pieces.edges_in.find(at); it != pieces.edges_in.end()) {
          for (const std::uint32_t k : it->second) {
            add({p[k], at, p[(pieces.next_edge[k] + 1) % p.size()]});
          }
        }
      }
    }
    if (sides.size() < 2) return std::nullopt;
    for (auto& [loop, rays] : sides) {
      if (rays.empty()) {
        return names_[loop] + " is touched by another loop at " + point_name(passages) +
               ", where it runs both ways along an edge";
      }
      std::sort(rays.begin(), rays.end(),
                [&at](const Ray& a, const Ray& b) { return angle_less(at, a.to, b.to); });
    }
    auto inside = [&](std::uint32_t loop, const Point2& w) {
      const std::vector<Ray>& rays = sides.at(loop);
      const Ray* before = &rays.back();
      for (const Ray& r : rays) {
        if (!angle_less(at, r.to, w)) break;
        before = &r;
      }
      return before->out == ccw_[loop];
    };
    for (auto a = sides.begin(); a != sides.end(); ++a) {
      for (auto b = std::next(a); b != sides.end(); ++b) {
        touching_.insert({a->first, b->first});
        bool b_in_a = false;
        bool b_out_of_a = false;
        bool a_in_b = false;
        for (const Ray& r : b->second) (inside(a->first, r.to) ? b_in_a : b_out_of_a) = true;
        for (const Ray& r : a->second) a_in_b = a_in_b || inside(b->first, r.to);
        if (a->first == 0) {
          if (b_out_of_a || a_in_b) return names_[b->first] + " is not inside " + names_[0];
        } else if (b_in_a || a_in_b) {
          return names_[a->first] + " and " + names_[b->first] + " overlap";
        }
      }
    }
    return std::nullopt;
  }

  std::optional<std::string> check_containment() const {
    // No crossings and no touching: each hole is wholly inside or wholly outside every
    // other loop, so one vertex tells. Parity tells for a pinched or bridged loop too: its
    // winding number is 0 or ±1.
    std::vector<Box> boxes;
    for (const CleanLoop& l : loops_) {
      Box b{l.points[0].x, l.points[0].x, l.points[0].y, l.points[0].y};
      for (const Point2& p : l.points) {
        b.xmin = std::min(b.xmin, p.x);
        b.xmax = std::max(b.xmax, p.x);
        b.ymin = std::min(b.ymin, p.y);
        b.ymax = std::max(b.ymax, p.y);
      }
      boxes.push_back(b);
    }
    for (std::uint32_t h = 1; h < loops_.size(); ++h) {
      if (touching_.count({0, h}) != 0) continue;
      if (!boxes[0].contains(boxes[h]) || !inside_loop(loops_[0].points, loops_[h].points[0])) {
        return names_[h] + " is not inside " + names_[0];
      }
    }
    for (std::uint32_t h = 1; h < loops_.size(); ++h) {
      for (std::uint32_t g = 1; g < loops_.size(); ++g) {
        if (g == h || !boxes[g].contains(boxes[h])) continue;
        if (touching_.count({std::min(g, h), std::max(g, h)}) != 0) continue;
        if (inside_loop(loops_[g].points, loops_[h].points[0])) {
          return names_[h] + " lies inside " + names_[g] + " (holes must not overlap)";
        }
      }
    }
    return std::nullopt;
  }

  std::vector<CleanLoop> loops_;
  std::span<const std::string> names_;
  // Points where loops touch or a loop passes again, with the loops' passages there.
  std::map<Point2, std::vector<Passage>> touches_;
  // Per loop: for each edge, the edge that runs along it the other way (empty: none).
  std::vector<std::vector<std::uint32_t>> bridge_partner_;
  std::vector<bool> pinched_;  // per loop: passes a vertex twice
  std::vector<Pieces> pieces_;
  std::set<std::pair<std::uint32_t, std::uint32_t>> touching_;
  std::vector<bool> ccw_;
};

}  // namespace

LoopCheck check_loops(std::span<const clipper::Loop2> loops,
                      std::span<const std::string> loop_names) {
  return Checker(loops, loop_names).run();
}

}  // namespace shadowgen::detail
