#include "loop_validation.h"

#include <algorithm>
#include <compare>
#include <cstdint>
#include <map>
#include <set>
#include <utility>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "clipper/predicates.h"
#include "clipper/segment_contact.h"
#include "loop_geometry.h"
#include "loop_pieces.h"

namespace shadowgen::scene::detail {

namespace {

using clipper::orient2d;
using clipper::Orientation;
using clipper::Point2;

struct Edge {
  Point2 a, b;
  clipper::Box2 box;
  std::uint32_t loop;
  std::uint32_t index;  // edge index = index of its first vertex in the clean loop
};

// A loop passes a point at one of its vertices, or inside one of its edges (touching
// another loop there).
struct Passage {
  std::uint32_t loop;
  std::uint32_t index;  // the vertex, or with inside_edge the edge, in the clean loop
  bool inside_edge;
  friend auto operator<=>(const Passage&, const Passage&) = default;
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
    if (!result.problem) {
      result.counter_clockwise = std::move(ccw_);
      result.shares_edges = !sharing_.empty();
    }
    return result;
  }

 private:
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
      } else {
        PiecesCheck pieces = check_pieces(loops_[l], bridge_partner_[l], names_[l], pieces_[l]);
        if (pieces.problem) return pieces.problem;
        ccw_[l] = pieces.counter_clockwise;
      }
    }
    for (const auto& [at, passages] : touches_) {
      if (auto problem = check_sides(at, passages)) return problem;
    }
    if (auto problem = check_containment()) return problem;
    return check_sharing_pairs();
  }

  std::string vertex_name(std::uint32_t loop, std::size_t clean_index) const {
    return detail::vertex_name(loops_[loop], clean_index);
  }
  std::string edge_name(const Edge& e) const {
    return vertex_name(e.loop, e.index) + "-" + vertex_name(e.loop, e.index + 1);
  }
  bool is_bridge(std::uint32_t loop, std::uint32_t edge) const {
    return !bridge_partner_[loop].empty() && bridge_partner_[loop][edge] != kNoEdge;
  }

  std::optional<std::string> sweep_edges() {
    std::vector<Edge> edges;
    for (std::uint32_t l = 0; l < loops_.size(); ++l) {
      const std::vector<Point2>& p = loops_[l].points;
      for (std::uint32_t i = 0; i < p.size(); ++i) {
        const Point2& a = p[i];
        const Point2& b = p[(i + 1) % p.size()];
        edges.push_back({a, b, clipper::box_of(a, b), l, i});
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
        if (partner.empty()) partner.assign(n, kNoEdge);
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
      // A shared segment: where the two loops lie is left to check_sharing_pairs.
      sharing_.insert({e.loop, f.loop});
      return std::nullopt;
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
        const Passage& s = passages[i];
        const Passage& t = passages[j];
        if (a.prev == b.prev || a.prev == b.next || a.next == b.prev || a.next == b.next) continue;
        if (sharing(s.loop, t.loop)) continue;  // directions in common: check_sharing_pairs
        if (!cross(a, b)) continue;
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
        const LoopPieces& pieces = pieces_[s.loop];
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
        if (sharing(a->first, b->first)) continue;  // directions in common: check_sharing_pairs
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
    std::vector<clipper::Box2> boxes;
    for (const CleanLoop& l : loops_) boxes.push_back(clipper::box_of(l.points));
    for (std::uint32_t h = 1; h < loops_.size(); ++h) {
      if (touching_.count({0, h}) != 0 || sharing(0, h)) continue;
      if (!boxes[0].contains(boxes[h]) || !inside_loop(loops_[0].points, loops_[h].points[0])) {
        return names_[h] + " is not inside " + names_[0];
      }
    }
    for (std::uint32_t h = 1; h < loops_.size(); ++h) {
      for (std::uint32_t g = 1; g < loops_.size(); ++g) {
        if (g == h || !boxes[g].contains(boxes[h])) continue;
        if (touching_.count({std::min(g, h), std::max(g, h)}) != 0 || sharing(g, h)) continue;
        if (inside_loop(loops_[g].points, loops_[h].points[0])) {
          return names_[h] + " lies inside " + names_[g] + " (holes must not overlap)";
        }
      }
    }
    return std::nullopt;
  }

  // Loops that share a segment meet along it, not only at points, so their sides cannot be
  // told from their directions: the clipper tells whether the hole lies in the outer loop
  // (nothing of it left outside), or two holes overlap (something in both). Pieces within
  // the rounding of the clipper's snapping are nothing (loop_validation.h).
  std::optional<std::string> check_sharing_pairs() const {
    auto something = [](const clipper::PolygonSet2& pieces) {
      return std::any_of(pieces.begin(), pieces.end(), [](const clipper::PolygonWithHoles2& p) {
        double bound = clipper::rounding_area_bound(p.outer);
        for (const clipper::Loop2& hole : p.holes) bound += clipper::rounding_area_bound(hole);
        return clipper::area(p) > bound;
      });
    };
    for (const auto& [g, h] : sharing_) {
      const clipper::PolygonSet2 first{{loops_[g].points, {}}};
      const clipper::PolygonSet2 second{{loops_[h].points, {}}};
      if (g == 0) {
        if (something(clipper::difference(second, first))) {
          return names_[h] + " is not inside " + names_[0];
        }
      } else if (something(clipper::intersection(first, second))) {
        return names_[g] + " and " + names_[h] + " overlap";
      }
    }
    return std::nullopt;
  }

  bool sharing(std::uint32_t a, std::uint32_t b) const {
    return sharing_.count({std::min(a, b), std::max(a, b)}) != 0;
  }

  std::vector<CleanLoop> loops_;
  std::span<const std::string> names_;
  // Points where loops touch or a loop passes again, with the loops' passages there.
  std::map<Point2, std::vector<Passage>> touches_;
  // Per loop: for each edge, the edge that runs along it the other way (empty: none).
  std::vector<std::vector<std::uint32_t>> bridge_partner_;
  std::vector<bool> pinched_;  // per loop: passes a vertex twice
  std::vector<LoopPieces> pieces_;
  std::set<std::pair<std::uint32_t, std::uint32_t>> touching_;
  // Pairs of loops (lower first) that share a segment of positive length.
  std::set<std::pair<std::uint32_t, std::uint32_t>> sharing_;
  std::vector<bool> ccw_;
};

}  // namespace

LoopCheck check_loops(std::span<const clipper::Loop2> loops,
                      std::span<const std::string> loop_names) {
  return Checker(loops, loop_names).run();
}

}  // namespace shadowgen::scene::detail
