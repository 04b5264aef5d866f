#include "clipper/clip.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "clipper/detail/boundary_graph.h"
#include "clipper/detail/crossing.h"
#include "clipper/detail/edge_noding.h"
#include "clipper/detail/point_location.h"
#include "clipper/detail/vertex_merge.h"
#include "clipper/normalize.h"
#include "clipper/predicates.h"

namespace shadowgen::clipper {
namespace {

using detail::crossing_point;
using detail::DirectedEdge;
using detail::Location;

// One operand as the clipper sees it: every loop (outer and hole alike) oriented so the
// region lies on its left.
using Boundary = std::vector<Loop2>;

bool has_vertex(const Loop2& loop, const Point2& v) {
  return std::find(loop.begin(), loop.end(), v) != loop.end();
}

bool has_vertex(const PolygonWithHoles2& polygon, const Point2& v) {
  return has_vertex(polygon.outer, v) ||
         std::any_of(polygon.holes.begin(), polygon.holes.end(),
                     [&v](const Loop2& hole) { return has_vertex(hole, v); });
}

Boundary boundary_of(const PolygonSet2& polygons) {
  Boundary loops;
  for (const PolygonWithHoles2& p : polygons) {
    loops.push_back(p.outer);
    for (const Loop2& h : p.holes) loops.push_back(h);
  }
  return loops;
}

struct Box {
  double xmin, xmax, ymin, ymax;
};

Box bounds(const Boundary& loops) {
  Box b{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const Loop2& l : loops) {
    for (const Point2& p : l) {
      b.xmin = std::min(b.xmin, p.x);
      b.xmax = std::max(b.xmax, p.x);
      b.ymin = std::min(b.ymin, p.y);
      b.ymax = std::max(b.ymax, p.y);
    }
  }
  return b;
}

bool overlap(const Box& a, const Box& b) {
  return a.xmin <= b.xmax && b.xmin <= a.xmax && a.ymin <= b.ymax && b.ymin <= a.ymax;
}

// An edge of one operand, addressed by loop and start vertex.
struct EdgeRef {
  int side;  // 0 subject, 1 clip
  int loop;
  int index;
};

// A point to be inserted into an edge of one operand.
struct Insertion {
  int loop;
  int index;
  detail::EdgePoint at;
};

// Finds every point where the two boundaries meet and records it for insertion into
// both. Candidate pairs come from a sweep over x; the rest are rejected by y-interval.
class IntersectionFinder {
 public:
  IntersectionFinder(const Boundary& subject, const Boundary& clip_region)
      : sides_{&subject, &clip_region} {}

  void run() {
    struct Item {
      Box box;
      EdgeRef edge;
    };
    std::vector<Item> items;
    for (int s = 0; s < 2; ++s) {
      const Boundary& loops = *sides_[s];
      for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
        const Loop2& loop = loops[l];
        const int n = static_cast<int>(loop.size());
        for (int i = 0; i < n; ++i) {
          const Point2& p = loop[i];
          const Point2& q = loop[i + 1 == n ? 0 : i + 1];
          items.push_back(
              {{std::min(p.x, q.x), std::max(p.x, q.x), std::min(p.y, q.y), std::max(p.y, q.y)},
               {s, l, i}});
        }
      }
    }
    std::sort(items.begin(), items.end(),
              [](const Item& a, const Item& b) { return a.box.xmin < b.box.xmin; });
    std::vector<const Item*> active[2];
    for (const Item& item : items) {
      const int other = 1 - item.edge.side;
      std::vector<const Item*>& candidates = active[other];
      std::size_t kept = 0;
      for (const Item* c : candidates) {
        // Kept unless left behind by the sweep (without branches: unpredictable).
        candidates[kept] = c;
        const bool live = c->box.xmax >= item.box.xmin;
        kept += live ? 1 : 0;
        if (live & (c->box.ymin <= item.box.ymax) & (item.box.ymin <= c->box.ymax)) {
          if (item.edge.side == 0) {
            intersect(item.edge, c->edge);
          } else {
            intersect(c->edge, item.edge);
          }
        }
      }
      candidates.resize(kept);
      active[item.edge.side].push_back(&item);
    }
  }

  std::vector<Insertion> insertions[2];
  std::unordered_set<Point2, Point2Hash> nodes;
  std::unordered_set<Point2, Point2Hash> crossings;  // the nodes that are rounded points
  detail::ErrorRadii radii;  // per crossing, its construction's error bound (clip.h)

 private:
  const Point2& start(const EdgeRef& e) const { return (*sides_[e.side])[e.loop][e.index]; }
  const Point2& end(const EdgeRef& e) const {
    const Loop2& loop = (*sides_[e.side])[e.loop];
    return loop[e.index + 1 == static_cast<int>(loop.size()) ? 0 : e.index + 1];
  }

  void insert(const EdgeRef& e, const Point2& p) {
    insertions[e.side].push_back({e.loop, e.index, {p}});
  }
  // The rounded crossing with the other operand's edge f0-f1, which orders it exactly.
  void insert_crossing(const EdgeRef& e, const Point2& p, const Point2& f0, const Point2& f1) {
    insertions[e.side].push_back({e.loop, e.index, {p, true, f0, f1}});
  }

  // An endpoint of one edge lying on the other: a touching point, already a vertex of
  // its own boundary, inserted into the other unless it is an endpoint there too.
  void touch(const Point2& p, const EdgeRef& host, const Point2& h0, const Point2& h1) {
    nodes.insert(p);
    if (p != h0 && p != h1) insert(host, p);
  }

  static double length2(const Point2& p, const Point2& q) {
    const double dx = q.x - p.x, dy = q.y - p.y;
    return dx * dx + dy * dy;
  }

  void intersect(const EdgeRef& a, const EdgeRef& b) {
    const Point2 &a0 = start(a), &a1 = end(a), &b0 = start(b), &b1 = end(b);
    const Orientation oa0 = orient2d(b0, b1, a0);
    const Orientation oa1 = orient2d(b0, b1, a1);
    if (oa0 == oa1 && oa0 != Orientation::kCollinear) return;
    const Orientation ob0 = orient2d(a0, a1, b0);
    const Orientation ob1 = orient2d(a0, a1, b1);
    if (ob0 == ob1 && ob0 != Orientation::kCollinear) return;
    if (oa0 != Orientation::kCollinear && oa1 != Orientation::kCollinear &&
        ob0 != Orientation::kCollinear && ob1 != Orientation::kCollinear) {
      const Point2 p = crossing_point(a0, a1, b0, b1);
      nodes.insert(p);
      crossings.insert(p);
      constexpr double u = 0x1p-53;
      const double shorter = std::sqrt(std::min(length2(a0, a1), length2(b0, b1)));
      const double radius = 4.0 * u * shorter + u * (std::fabs(p.x) + std::fabs(p.y));
      double& r = radii[p];
      r = std::max(r, radius);
      insert_crossing(a, p, b0, b1);
      insert_crossing(b, p, a0, a1);
      return;
    }
    // Touching or collinear overlap: every endpoint lying on the other segment.
    if (oa0 == Orientation::kCollinear && on_segment(b0, b1, a0)) touch(a0, b, b0, b1);
    if (oa1 == Orientation::kCollinear && on_segment(b0, b1, a1)) touch(a1, b, b0, b1);
    if (ob0 == Orientation::kCollinear && on_segment(a0, a1, b0)) touch(b0, a, a0, a1);
    if (ob1 == Orientation::kCollinear && on_segment(a0, a1, b1)) touch(b1, a, a0, a1);
  }

  const Boundary* sides_[2];
};

// Where a loop of one operand touches another loop of the same operand (a hole touching
// its outer loop, two polygons of a set meeting at a point), the touching vertex lies
// inside an edge of the other loop. Inserting it there makes it a vertex of both, so the
// traversal and the split at repeated vertices see the touch. Decided exactly.
std::vector<Insertion> self_touches(const Boundary& loops) {
  // A sweep over the vertices in x. An edge enters at its left end, itself a vertex, so
  // one sort serves both; it is tested against the vertices of the other loops until the
  // sweep has passed its right end.
  struct Vertex {
    double x;
    int loop;
    int index;
  };
  struct Edge {
    double xmax, ymin, ymax;
    int loop;
    int index;
  };
  std::size_t count = 0;
  for (const Loop2& loop : loops) count += loop.size();
  std::vector<Vertex> vertices;
  vertices.reserve(count);
  for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
    for (int i = 0; i < static_cast<int>(loops[l].size()); ++i) {
      vertices.push_back({loops[l][i].x, l, i});
    }
  }
  std::sort(vertices.begin(), vertices.end(),
            [](const Vertex& a, const Vertex& b) { return a.x < b.x; });
  std::vector<Edge> active;
  // Activates edge i of loop l (from vertex i to the next) when the sweep stands at its
  // left end: at its start (at_start) or at its end. A vertical edge enters at its start,
  // so each edge enters exactly once.
  auto enter = [&](int l, int i, bool at_start) {
    const Loop2& loop = loops[l];
    const Point2& p = loop[i];
    const Point2& q = loop[i + 1 == static_cast<int>(loop.size()) ? 0 : i + 1];
    if ((p.x <= q.x) != at_start) return;
    active.push_back({std::max(p.x, q.x), std::min(p.y, q.y), std::max(p.y, q.y), l, i});
  };
  std::vector<Insertion> found;
  std::size_t next = 0;
  for (const Vertex& vertex : vertices) {
    for (; next < vertices.size() && vertices[next].x <= vertex.x; ++next) {
      const Vertex& v = vertices[next];
      const int n = static_cast<int>(loops[v.loop].size());
      enter(v.loop, v.index, true);                              // the edge leaving v
      enter(v.loop, v.index == 0 ? n - 1 : v.index - 1, false);  // the edge arriving at v
    }
    const Point2& p = loops[vertex.loop][vertex.index];
    std::size_t kept = 0;
    for (std::size_t k = 0; k < active.size(); ++k) {
      // Kept unless the sweep has passed it; written without branches, as which edges
      // drop out is unpredictable and the test is the whole cost of this loop.
      const Edge e = active[k];
      active[kept] = e;
      kept += e.xmax >= p.x ? 1 : 0;
      const bool candidate =
          (e.xmax >= p.x) & (e.loop != vertex.loop) & (p.y >= e.ymin) & (p.y <= e.ymax);
      if (!candidate) continue;
      const Loop2& loop = loops[e.loop];
      const Point2& a = loop[e.index];
      const Point2& b = loop[(e.index + 1) % loop.size()];
      if (p == a || p == b) continue;
      if (orient2d(a, b, p) == Orientation::kCollinear) found.push_back({e.loop, e.index, {p}});
    }
    active.resize(kept);
  }
  return found;
}

// One loop of an operand with the intersection points inserted in order along each edge
// (detail::AlongSegment). Each vertex remembers where it came from, because sides are decided on
// the original edges: exact input, never a rounded crossing point.
struct SplitLoop {
  Loop2 points;
  std::vector<int> original;  // index of the input vertex, or -1 for an inserted point
  std::vector<int> edge;      // input edge that the edge leaving this vertex lies on
  std::vector<char> node;     // whether the point is a node (looked up once, here)
};
using SplitBoundary = std::vector<SplitLoop>;

// `nodes`, when given, marks which points are nodes: every inserted point is one (it was
// inserted where the boundaries meet), an input vertex when it is in the set.
SplitBoundary with_insertions(const Boundary& loops, std::vector<Insertion>& insertions,
                              const std::unordered_set<Point2, Point2Hash>* nodes = nullptr) {
  std::sort(insertions.begin(), insertions.end(), [](const Insertion& a, const Insertion& b) {
    return a.loop != b.loop ? a.loop < b.loop : a.index < b.index;
  });
  SplitBoundary out(loops.size());
  std::size_t k = 0;
  for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
    const Loop2& loop = loops[l];
    SplitLoop& result = out[l];
    result.points.reserve(loop.size());
    const int n = static_cast<int>(loop.size());
    auto push = [&result, nodes](const Point2& p, int original, int edge) {
      if (!result.points.empty() && result.points.back() == p) return;
      result.points.push_back(p);
      result.original.push_back(original);
      result.edge.push_back(edge);
      result.node.push_back(nodes != nullptr && (original < 0 || nodes->count(p) != 0));
    };
    for (int i = 0; i < n; ++i) {
      const Point2& p = loop[i];
      const Point2& q = loop[i + 1 == n ? 0 : i + 1];
      push(p, i, i);
      const std::size_t first = k;
      while (k < insertions.size() && insertions[k].loop == l && insertions[k].index == i) ++k;
      if (k == first) continue;
      const detail::ExactlyAlongSegment along(p, q);
      std::sort(insertions.begin() + static_cast<std::ptrdiff_t>(first),
                insertions.begin() + static_cast<std::ptrdiff_t>(k),
                [&](const Insertion& a, const Insertion& b) { return along(a.at, b.at); });
      for (std::size_t j = first; j < k; ++j) {
        if (insertions[j].at.point != q) push(insertions[j].at.point, -1, i);
      }
    }
    while (result.points.size() > 1 && result.points.back() == result.points.front()) {
      result.points.pop_back();
      result.original.pop_back();
      result.edge.pop_back();
      result.node.pop_back();
    }
  }
  return out;
}

Boundary self_noded(Boundary loops) {
  if (loops.size() < 2) return loops;  // a simple loop touches no other
  std::vector<Insertion> touches = self_touches(loops);
  if (touches.empty()) return loops;
  SplitBoundary split = with_insertions(loops, touches);
  for (std::size_t l = 0; l < loops.size(); ++l) loops[l] = std::move(split[l].points);
  return loops;
}

// How a boundary passes through a node, told in input geometry. At one of its own input
// vertices (then the node is exact) it turns there: `from` is the previous input vertex,
// `to` the next. Anywhere else the node was inserted into one of its input edges, and the
// boundary runs straight along that edge from `from` to `to`.
struct Pass {
  bool at_vertex;
  Point2 from;
  Point2 to;
};
using PassMap = std::unordered_map<Point2, std::vector<Pass>, Point2Hash>;

PassMap passes_through(const Boundary& loops, const SplitBoundary& split) {
  PassMap passes;
  for (std::size_t l = 0; l < split.size(); ++l) {
    const Loop2& input = loops[l];
    const SplitLoop& loop = split[l];
    const int n = static_cast<int>(input.size());
    for (std::size_t i = 0; i < loop.points.size(); ++i) {
      if (!loop.node[i]) continue;
      const int e = loop.edge[i];
      if (loop.original[i] >= 0) {
        const int v = loop.original[i];
        passes[loop.points[i]].push_back({true, input[(v + n - 1) % n], input[(v + 1) % n]});
      } else {
        passes[loop.points[i]].push_back({false, input[e], input[(e + 1) % n]});
      }
    }
  }
  return passes;
}

enum class Side { kInside, kOutside, kSharedSame, kSharedOpposite };

// Does c lie on the ray from v through b?
bool on_ray(const Point2& v, const Point2& b, const Point2& c) {
  if (orient2d(v, b, c) != Orientation::kCollinear) return false;
  return (b.x - v.x) * (c.x - v.x) + (b.y - v.y) * (c.y - v.y) > 0.0;
}

// Is direction point w strictly inside the angle swept counter-clockwise at v from `to`
// round to `from` (the region left of from -> v -> to)?
bool in_sector(const Point2& v, const Pass& pass, const Point2& w) {
  const Orientation corner = orient2d(pass.from, v, pass.to);
  const bool left_of_next = orient2d(v, pass.to, w) == Orientation::kCounterClockwise;
  const bool right_of_prev = orient2d(v, pass.from, w) == Orientation::kClockwise;
  return corner == Orientation::kCounterClockwise ? left_of_next && right_of_prev
                                                  : left_of_next || right_of_prev;
}

// Which side of the other operand the stretch leaving node v along the input edge
// (e0 -> e1) lies on, judged against one pass of the other boundary. This is the exact
// local form of the entry/exit test (a touch does not flip the state, a crossing does),
// asked of input points wherever the node itself is a rounded crossing:
//   - a pass straight along an input edge f: where v lies exactly on f, the stretch lies
//     on e1's side of f (e0's if e1 is on f's line; on f itself if both are); where v is
//     the rounded crossing of the stretch's edge with f, on e1's side; where v is off f
//     (a rounded crossing with some other edge fell on it), on v's own side;
//   - a pass turning at an input vertex v of the other operand (v exact): if v lies on the
//     stretch's input edge, the sector test at v is exact. If not, v is only where the
//     rounded crossing of the stretch's edge with one of the two edges at v fell, and the
//     stretch lies on e1's side of the edge it crossed.
Side side_against(const Point2& v, const Point2& e0, const Point2& e1, const Pass& pass) {
  if (!pass.at_vertex) {
    const Orientation s1 = orient2d(pass.from, pass.to, e1);
    const Orientation s0 = orient2d(pass.from, pass.to, e0);
    if (s1 == Orientation::kCollinear && s0 == Orientation::kCollinear) {
      const double dot =
          (e1.x - e0.x) * (pass.to.x - pass.from.x) + (e1.y - e0.y) * (pass.to.y - pass.from.y);
      return dot > 0.0 ? Side::kSharedSame : Side::kSharedOpposite;
    }
    Orientation side;
    const Orientation sv = orient2d(pass.from, pass.to, v);
    if (sv == Orientation::kCollinear) {
      side = s1 != Orientation::kCollinear ? s1 : s0;  // v on f: the stretch leaves it
    } else if (s0 != Orientation::kCollinear && s1 != Orientation::kCollinear && s0 != s1 &&
               orient2d(e0, e1, pass.from) != Orientation::kCollinear &&
               orient2d(e0, e1, pass.to) != Orientation::kCollinear &&
               orient2d(e0, e1, pass.from) != orient2d(e0, e1, pass.to) &&
               crossing_point(e0, e1, pass.from, pass.to) == v) {
      side = s1;  // v is the rounded crossing of the two: the stretch is past it
    } else {
      side = sv;  // v is off f (a crossing with another edge fell here): it starts on v's side
    }
    return side == Orientation::kCounterClockwise ? Side::kInside : Side::kOutside;
  }
  if (orient2d(e0, e1, v) == Orientation::kCollinear) {
    if (on_ray(v, pass.to, e1)) return Side::kSharedSame;
    if (on_ray(v, pass.from, e1)) return Side::kSharedOpposite;
    return in_sector(v, pass, e1) ? Side::kInside : Side::kOutside;
  }
  // Does the stretch's input edge properly cross the input edge f0 -> f1?
  auto crosses = [&](const Point2& f0, const Point2& f1) {
    const Orientation a = orient2d(f0, f1, e0), b = orient2d(f0, f1, e1);
    const Orientation c = orient2d(e0, e1, f0), d = orient2d(e0, e1, f1);
    return a != Orientation::kCollinear && b != Orientation::kCollinear && a != b &&
           c != Orientation::kCollinear && d != Orientation::kCollinear && c != d;
  };
  // Of the two edges at v, the one whose rounded crossing with the stretch's edge is v
  // itself (a crossing with the other one, if any, made a node of its own); failing that,
  // any one the stretch's edge crosses.
  auto side_of = [&](const Point2& f0, const Point2& f1) {
    return orient2d(f0, f1, e1) == Orientation::kCounterClockwise ? Side::kInside : Side::kOutside;
  };
  const bool crosses_in = crosses(pass.from, v), crosses_out = crosses(v, pass.to);
  const bool lands_in = crosses_in && crossing_point(pass.from, v, e0, e1) == v;
  const bool lands_out = crosses_out && crossing_point(v, pass.to, e0, e1) == v;
  // Both crossings landed on v: the stretch cut across the corner and is past both, in
  // the sector its direction points into.
  if (lands_in && lands_out) return in_sector(v, pass, e1) ? Side::kInside : Side::kOutside;
  if (lands_in) return side_of(pass.from, v);
  if (lands_out) return side_of(v, pass.to);
  if (crosses_in) return side_of(pass.from, v);
  if (crosses_out) return side_of(v, pass.to);
  const Point2 ahead{v.x + (e1.x - e0.x), v.y + (e1.y - e0.y)};
  return in_sector(v, pass, ahead) ? Side::kInside : Side::kOutside;
}

// Is the direction just counter-clockwise of the ray v -> r in the left sector of `pass`?
bool just_past_ray_in_sector(const Point2& v, const Point2& r, const Pass& pass) {
  if (on_ray(v, pass.to, r)) return true;     // the sector starts at `to`
  if (on_ray(v, pass.from, r)) return false;  // and ends at `from`
  return in_sector(v, pass, r);
}

// Against all passes through v. One pass: its side. Several (loops touching at v, such as
// a hole touching its outer loop, or two polygons of a set meeting at a point): the other
// region near v is where the winding number is 1. Each pass adds one to the winding of
// its left sector (less a constant for clockwise loops), so a direction is inside exactly
// when it lies in as many left sectors as a direction known to be inside: the one just
// counter-clockwise of a pass's outgoing edge, which has the region on its left.
Side side_of_edge(const Point2& v, const Point2& e0, const Point2& e1,
                  const std::vector<Pass>& passes) {
  if (passes.size() == 1) return side_against(v, e0, e1, passes.front());
  int count = 0;
  for (const Pass& pass : passes) {
    const Side s = side_against(v, e0, e1, pass);
    if (s == Side::kSharedSame || s == Side::kSharedOpposite) return s;
    if (s == Side::kInside) ++count;
  }
  int reference = 0;
  for (const Pass& pass : passes) {
    if (just_past_ray_in_sector(v, passes.front().to, pass)) ++reference;
  }
  return count >= reference ? Side::kInside : Side::kOutside;
}

// Several passes through v of which one was put there by a rounded crossing: crossings
// less than a rounding apart (a boundary cutting through the thin tip of a spike) have
// merged into one node, and no local test at v can tell in which order they were crossed.
bool merged_crossings(const Point2& v, const std::vector<Pass>& passes) {
  if (passes.size() < 2) return false;
  return std::any_of(passes.begin(), passes.end(), [&v](const Pass& p) {
    return !p.at_vertex && orient2d(p.from, p.to, v) != Orientation::kCollinear;
  });
}

// The edges of one operand's boundary split by side of the other operand.
struct ClassifiedEdges {
  std::vector<DirectedEdge> inside, outside, shared_same, shared_opposite;
};

struct Segment {
  Point2 from, to;
  friend bool operator==(const Segment&, const Segment&) = default;
};
struct SegmentHash {
  std::size_t operator()(const Segment& s) const noexcept {
    const Point2Hash h;
    return h(s.from) * 31u + h(s.to);
  }
};
// The input edge a split edge lies on, in its operand's direction (region on its left).
struct InputEdge {
  Point2 from, to;
};
using SegmentMap = std::unordered_map<Segment, InputEdge, SegmentHash>;

// The split edges of one operand that run from node to node: the only ones that can be
// the very same segment as one of the other operand's.
SegmentMap node_to_node_segments(const Boundary& loops, const SplitBoundary& split) {
  SegmentMap out;
  for (std::size_t l = 0; l < split.size(); ++l) {
    const SplitLoop& loop = split[l];
    const Loop2& input = loops[l];
    const std::size_t n = loop.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (loop.node[i] && loop.node[(i + 1) % n]) {
        const int e = loop.edge[i];
        out.emplace(Segment{loop.points[i], loop.points[(i + 1) % n]},
                    InputEdge{input[e], input[(e + 1) % input.size()]});
      }
    }
  }
  return out;
}

// Where the other operand's boundary runs both ways along one segment, rounding has
// closed a part of it to zero width: a needle of its region (the two input edges face
// each other's region side) or a crack in it. The two copies bound nothing, and the
// region around them is outside a needle, inside a crack. `forward` is the copy running
// with the stretch, `backward` the other; the backward edge lies on the forward edge's
// region side exactly for a needle. Empty when the input edges do not tell (the backward
// edge crosses the forward edge's line).
std::optional<Side> side_of_collapsed(const InputEdge& forward, const InputEdge& backward) {
  const Orientation a = orient2d(forward.from, forward.to, backward.from);
  const Orientation b = orient2d(forward.from, forward.to, backward.to);
  const Orientation side = a == Orientation::kCollinear ? b : a;
  if (side == Orientation::kCollinear || (b != Orientation::kCollinear && b != side)) {
    return std::nullopt;
  }
  return side == Orientation::kCounterClockwise ? Side::kOutside : Side::kInside;
}

ClassifiedEdges classify(const Boundary& loops, const SplitBoundary& split,
                         const Boundary& other_loops, const PassMap& other_passes,
                         const SegmentMap& other_segments) {
  ClassifiedEdges out;
  auto bucket = [&out](Side s) -> std::vector<DirectedEdge>& {
    switch (s) {
      case Side::kInside:
        return out.inside;
      case Side::kOutside:
        return out.outside;
      case Side::kSharedSame:
        return out.shared_same;
      case Side::kSharedOpposite:
        break;
    }
    return out.shared_opposite;
  };
  for (std::size_t l = 0; l < split.size(); ++l) {
    const Loop2& input = loops[l];
    const Loop2& loop = split[l].points;
    const std::size_t n = loop.size();
    std::size_t first_node = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (split[l].node[i]) {
        first_node = i;
        break;
      }
    }
    if (first_node == n) {
      // Untouched by the other boundary: the whole loop lies on one side.
      const bool inside = detail::locate(loop[0], other_loops) == Location::kInside;
      auto& dst = inside ? out.inside : out.outside;
      for (std::size_t i = 0; i < n; ++i) dst.push_back({loop[i], loop[(i + 1) % n]});
      continue;
    }
    // Each stretch from a node to the next lies on one side: decide it at its start.
    std::vector<DirectedEdge>* dst = nullptr;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = (first_node + k) % n;
      const Point2& v = loop[i];
      const Point2& w = loop[(i + 1) % n];
      if (split[l].node[i]) {
        const auto it = other_passes.find(v);
        const int e = split[l].edge[i];
        const Point2& e0 = input[e];
        const Point2& e1 = input[(e + 1) % input.size()];
        // The same segment in both boundaries (after rounding, whatever the input edges
        // were) is shared: deciding it any other way would leave the two copies on
        // different sides of a zero-width gap.
        const auto same = other_segments.find({v, w});
        const auto opposite = other_segments.find({w, v});
        std::optional<Side> collapsed;
        if (same != other_segments.end() && opposite != other_segments.end()) {
          collapsed = side_of_collapsed(same->second, opposite->second);
        }
        if (collapsed) {
          dst = &bucket(*collapsed);
        } else if (same != other_segments.end()) {
          dst = &out.shared_same;
        } else if (opposite != other_segments.end()) {
          dst = &out.shared_opposite;
        } else if (it != other_passes.end() && !merged_crossings(v, it->second)) {
          dst = &bucket(side_of_edge(v, e0, e1, it->second));
        } else {
          // No usable local picture: decide at the middle of the stretch's first edge.
          dst = detail::locate_midpoint(v, w, other_loops) == Location::kInside ? &out.inside
                                                                                : &out.outside;
        }
      }
      dst->push_back({v, w});
    }
  }
  return out;
}

void append(std::vector<DirectedEdge>& dst, const std::vector<DirectedEdge>& src) {
  dst.insert(dst.end(), src.begin(), src.end());
}

void append_reversed(std::vector<DirectedEdge>& dst, const std::vector<DirectedEdge>& src) {
  for (const DirectedEdge& e : src) dst.push_back({e.to, e.from});
}

}  // namespace

ClipResult clip(const PolygonSet2& subject, const PolygonSet2& clip_region) {
  ClipResult result;
  PolygonSet2 a = normalized(subject);
  const PolygonSet2 b = normalized(clip_region);
  if (a.empty()) return result;
  const Boundary a_loops = self_noded(boundary_of(a));
  const Boundary b_loops = self_noded(boundary_of(b));
  if (b.empty() || !overlap(bounds(a_loops), bounds(b_loops))) {
    result.outside = std::move(a);
    return result;
  }

  IntersectionFinder finder(a_loops, b_loops);
  finder.run();
  const SplitBoundary a_split = with_insertions(a_loops, finder.insertions[0], &finder.nodes);
  const SplitBoundary b_split = with_insertions(b_loops, finder.insertions[1], &finder.nodes);
  const PassMap a_passes = passes_through(a_loops, a_split);
  const PassMap b_passes = passes_through(b_loops, b_split);
  const SegmentMap a_segments = node_to_node_segments(a_loops, a_split);
  const SegmentMap b_segments = node_to_node_segments(b_loops, b_split);
  const ClassifiedEdges a_edges = classify(a_loops, a_split, b_loops, b_passes, b_segments);
  const ClassifiedEdges b_edges = classify(b_loops, b_split, a_loops, a_passes, a_segments);

  // subject ∩ clip: the subject inside the clip, the clip inside the subject, and the
  // shared stretches where both regions lie on the same side (taken once).
  std::vector<DirectedEdge> inside_edges = a_edges.inside;
  append(inside_edges, b_edges.inside);
  append(inside_edges, a_edges.shared_same);
  // subject − clip: the subject outside the clip, the clip inside the subject reversed,
  // and the shared stretches where the clip lies on the far side.
  std::vector<DirectedEdge> outside_edges = a_edges.outside;
  append_reversed(outside_edges, b_edges.inside);
  append(outside_edges, a_edges.shared_opposite);

  // Rounded crossings may have moved stretches into contact: node them. A crossing an ulp
  // beside a vertex goes to that vertex (and the edges it moved are noded). And a vertex the
  // operands bring from earlier clips may lie a rounding off an edge it was made on,
  // folding the traced boundary back along that edge: snap it onto the edge so the fold
  // cancels (detail/snap.h). A snapped edge moved by a hair and may now cross a
  // neighbour: node once more. Then trace.
  auto is_input = [&a_loops, &b_loops](const Point2& p) {
    auto on = [&p](const Loop2& loop) { return has_vertex(loop, p); };
    return std::any_of(a_loops.begin(), a_loops.end(), on) ||
           std::any_of(b_loops.begin(), b_loops.end(), on);
  };
  auto finish = [&finder, &is_input](std::vector<DirectedEdge> edges) {
    std::unordered_set<Point2, Point2Hash> made;  // by the noding, beside the crossings
    edges = detail::node_edges(std::move(edges), finder.crossings, nullptr, &made);
    if (!made.empty()) made.insert(finder.crossings.begin(), finder.crossings.end());
    std::unordered_set<Point2, Point2Hash> merged;
    edges = detail::merge_close_vertices(std::move(edges), made.empty() ? finder.crossings : made,
                                         is_input, merged, &finder.radii);
    if (!merged.empty()) edges = detail::node_edges(std::move(edges), merged);
    std::unordered_set<Point2, Point2Hash> snapped;
    edges = detail::snap_vertices_onto_edges(std::move(edges), nullptr, &snapped);
    if (!snapped.empty()) edges = detail::node_edges(std::move(edges), snapped);
    return detail::assemble_polygons(edges);
  };
  result.inside = finish(std::move(inside_edges));
  result.outside = finish(std::move(outside_edges));
  return result;
}

ClipResult clip(const PolygonWithHoles2& subject, const PolygonWithHoles2& clip_region) {
  return clip(PolygonSet2{subject}, PolygonSet2{clip_region});
}

ClipResult clip(const PolygonWithHoles2& subject, std::span<const PolygonWithHoles2> clips) {
  // The outside pieces left by one clip are the subject of the next, so the inside
  // pieces of different clips never overlap even where the clips do.
  // Re-clipping rounded pieces against clips that overlap earlier ones can leave slivers
  // that exist only because of that rounding; pieces within the rounding bound go, unless
  // every vertex of theirs was already a vertex of the step's operands: such a piece was
  // not made by rounding (a thin subject the clip does not touch comes back whole).
  auto drop_rounding_slivers = [](PolygonSet2& set, const PolygonSet2& before,
                                  const PolygonWithHoles2& c) {
    auto is_operand_vertex = [&](const Point2& v) {
      return has_vertex(c, v) || std::any_of(before.begin(), before.end(),
                                             [&v](const auto& p) { return has_vertex(p, v); });
    };
    std::erase_if(set, [&](const PolygonWithHoles2& p) {
      if (std::fabs(signed_area(p.outer)) > rounding_area_bound(p.outer)) return false;
      return !std::all_of(p.outer.begin(), p.outer.end(), is_operand_vertex);
    });
  };
  ClipResult result;
  result.outside = normalized(PolygonSet2{subject});
  for (const PolygonWithHoles2& c : clips) {
    if (result.outside.empty()) break;
    ClipResult step = clip(result.outside, PolygonSet2{c});
    drop_rounding_slivers(step.inside, result.outside, c);
    drop_rounding_slivers(step.outside, result.outside, c);
    for (PolygonWithHoles2& p : step.inside) result.inside.push_back(std::move(p));
    result.outside = std::move(step.outside);
  }
  return result;
}

PolygonSet2 intersection(const PolygonSet2& a, const PolygonSet2& b) { return clip(a, b).inside; }

PolygonSet2 difference(const PolygonSet2& a, const PolygonSet2& b) { return clip(a, b).outside; }

}  // namespace shadowgen::clipper
