#include "loop_validation.h"

#include <algorithm>
#include <cstdint>
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

// Where loop `e.loop` passes through point x of edge e: the points before and after x
// along the loop.
struct Corner {
  Point2 prev, at, next;
};

// Strictly inside, near the corner, on the interior side of a loop traversed
// prev -> at -> next: the interior lies to the left of a counter-clockwise loop and to
// the right of a clockwise one.
bool locally_inside(Corner c, bool counter_clockwise, const Point2& w) {
  if (!counter_clockwise) std::swap(c.prev, c.next);
  const int turn = sign(orient2d(c.prev, c.at, c.next));
  const bool left_of_in = orient2d(c.prev, c.at, w) == Orientation::kCounterClockwise;
  const bool left_of_out = orient2d(c.at, c.next, w) == Orientation::kCounterClockwise;
  if (turn > 0) return left_of_in && left_of_out;
  return left_of_in || left_of_out;  // reflex, or straight (then both agree)
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

class Checker {
 public:
  Checker(std::span<const clipper::Loop2> loops, std::span<const std::string> names)
      : names_(names) {
    loops_.reserve(loops.size());
    for (const clipper::Loop2& loop : loops) loops_.push_back(clean(loop));
  }

  LoopCheck run() {
    LoopCheck result;
    result.problem = check();
    if (!result.problem) result.counter_clockwise = std::move(ccw_);
    return result;
  }

 private:
  std::optional<std::string> check() {
    for (std::size_t l = 0; l < loops_.size(); ++l) {
      if (loops_[l].points.size() < 3) return names_[l] + " has no area in the face's plane";
    }
    if (auto problem = sweep_edges()) return problem;
    ccw_.reserve(loops_.size());
    for (const CleanLoop& loop : loops_) ccw_.push_back(clipper::is_counter_clockwise(loop.points));
    for (const Touch& t : touches_) {
      if (auto problem = check_touch(t)) return problem;
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
    if (e.loop == f.loop) {
      const std::size_t n = loops_[e.loop].points.size();
      const bool adjacent = (e.index + 1) % n == f.index || (f.index + 1) % n == e.index;
      if (adjacent) {
        if (m.contact != clipper::Contact::kOverlap) return std::nullopt;  // their shared vertex
        const std::size_t shared = (e.index + 1) % n == f.index ? f.index : e.index;
        return names_[e.loop] + " doubles back on itself at vertex " + vertex_name(e.loop, shared);
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
    touches_.push_back({e, f, m.at});
    return std::nullopt;
  }

  struct Touch {
    Edge e, f;  // e.loop < f.loop
    Point2 at;
  };

  Corner corner(const Edge& e, const Point2& x) const {
    const std::vector<Point2>& p = loops_[e.loop].points;
    const std::size_t n = p.size();
    if (x == e.a) return {p[(e.index + n - 1) % n], x, e.b};
    if (x == e.b) return {e.a, x, p[(e.index + 2) % n]};
    return {e.a, x, e.b};
  }

  std::string point_name(const Touch& t) const {
    const Edge& e = t.at == t.e.a || t.at == t.e.b ? t.e : t.f;
    const std::size_t i = t.at == e.a ? e.index : e.index + 1;
    return "vertex " + vertex_name(e.loop, i) + " of " + names_[e.loop];
  }

  // Two loops that touch at a point must not cross there, and must lie on the proper
  // sides of each other: a hole inside the outer loop, two holes outside each other.
  std::optional<std::string> check_touch(const Touch& t) {
    const std::uint32_t a = t.e.loop;
    const std::uint32_t b = t.f.loop;
    touching_.insert({a, b});
    const Corner ca = corner(t.e, t.at);
    const Corner cb = corner(t.f, t.at);
    const bool b_prev_in_a = locally_inside(ca, ccw_[a], cb.prev);
    const bool b_next_in_a = locally_inside(ca, ccw_[a], cb.next);
    const bool a_prev_in_b = locally_inside(cb, ccw_[b], ca.prev);
    const bool a_next_in_b = locally_inside(cb, ccw_[b], ca.next);
    if (b_prev_in_a != b_next_in_a || a_prev_in_b != a_next_in_b) {
      return names_[b] + " crosses " + names_[a] + " at " + point_name(t);
    }
    if (a == 0) {
      if (!b_prev_in_a || a_prev_in_b) return names_[b] + " is not inside " + names_[0];
    } else if (b_prev_in_a || a_prev_in_b) {
      return names_[a] + " and " + names_[b] + " overlap";
    }
    return std::nullopt;
  }

  std::optional<std::string> check_containment() const {
    // No crossings and no touching: each hole is wholly inside or wholly outside every
    // other loop, so one vertex tells.
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
  std::vector<Touch> touches_;
  std::set<std::pair<std::uint32_t, std::uint32_t>> touching_;
  std::vector<bool> ccw_;
};

}  // namespace

LoopCheck check_loops(std::span<const clipper::Loop2> loops,
                      std::span<const std::string> loop_names) {
  return Checker(loops, loop_names).run();
}

}  // namespace shadowgen::detail
