#include "boundary_graph.h"

#include <algorithm>
#include <cmath>

#include "clipper/box.h"
#include "clipper/normalize.h"
#include "clipper/predicates.h"
#include "point_location.h"

namespace shadowgen::clipper::detail {
namespace {

// Clockwise order of directions around v, starting just clockwise of the ray v -> back:
// rank 0 strictly right of the ray, 1 straight ahead (opposite the ray), 2 strictly
// left, 3 along the ray itself (turning straight back: the last resort).
int clockwise_rank(const Point2& v, const Point2& back, const Point2& w) {
  switch (orient2d(v, back, w)) {
    case Orientation::kClockwise:
      return 0;
    case Orientation::kCounterClockwise:
      return 2;
    case Orientation::kCollinear:
      break;
  }
  const double dot = (back.x - v.x) * (w.x - v.x) + (back.y - v.y) * (w.y - v.y);
  return dot < 0.0 ? 1 : 3;
}

// True when w1 comes strictly before w2 clockwise from the ray v -> back.
bool clockwise_before(const Point2& v, const Point2& back, const Point2& w1, const Point2& w2) {
  const int r1 = clockwise_rank(v, back, w1);
  const int r2 = clockwise_rank(v, back, w2);
  if (r1 != r2) return r1 < r2;
  if (r1 == 1 || r1 == 3) return false;
  return orient2d(v, w1, w2) == Orientation::kClockwise;
}

// Closed walks through the edges, one after another: their points, and their ids
// (PointIndex) for the split at repeated vertices; walk k is [starts[k], starts[k + 1]).
struct Walks {
  Loop2 points;
  std::vector<std::size_t> ids;
  std::vector<std::size_t> starts;
};

// The storage of one tracing, kept per thread from call to call: the clipper traces twice
// per clip (inside and outside pieces), and for the small polygons of shadow generation
// allocating it anew took about a tenth of the tracing's time.
struct TraceWorkspace {
  std::vector<std::size_t> first, leaving, fill, position, stack_ids;
  std::vector<char> used;
  Walks walks;
};

// Tracings of more edges than this give their storage back when done.
constexpr std::size_t kKeptEdges = std::size_t{1} << 14;

constexpr std::size_t kNotOnStack = static_cast<std::size_t>(-1);

class Tracer {
 public:
  Tracer(const std::vector<DirectedEdge>& edges, std::size_t point_count, TraceWorkspace& w)
      : edges_(edges),
        point_count_(point_count),
        first_(w.first),
        leaving_(w.leaving),
        used_(w.used) {
    // Edges leaving each point, in one array (counting sort by start point).
    first_.assign(point_count + 1, 0);
    for (const DirectedEdge& e : edges) ++first_[e.from_id + 1];
    for (std::size_t v = 0; v < point_count; ++v) first_[v + 1] += first_[v];
    leaving_.resize(edges.size());
    std::vector<std::size_t>& fill = w.fill;
    fill.assign(first_.begin(), first_.end() - 1);
    for (std::size_t e = 0; e < edges.size(); ++e) leaving_[fill[edges[e].from_id]++] = e;
    used_.assign(edges.size(), 0);
  }

  std::size_t point_count() const { return point_count_; }

  void trace(Walks& walks) {
    walks.points.clear();
    walks.ids.clear();
    walks.starts.assign(1, 0);
    for (std::size_t start = 0; start < edges_.size(); ++start) {
      if (used_[start]) continue;
      std::size_t e = start;
      used_[e] = 1;
      const std::size_t origin = edges_[start].from_id;
      bool closed = true;
      while (true) {
        walks.points.push_back(edges_[e].from);
        walks.ids.push_back(edges_[e].from_id);
        const Point2& back = edges_[e].from;
        const Point2& v = edges_[e].to;
        const std::size_t vid = edges_[e].to_id;
        // Candidates: unused edges leaving v, and the first edge when v closes the walk.
        std::size_t best = kNone;
        for (std::size_t k = first_[vid]; k < first_[vid + 1]; ++k) {
          const std::size_t c = leaving_[k];
          if (used_[c] && !(c == start && vid == origin)) continue;
          if (best == kNone || clockwise_before(v, back, edges_[c].to, edges_[best].to)) {
            best = c;
          }
        }
        if (best == kNone) {
          // A dead end: the edges do not close here. No loop is made of them rather
          // than one closed by an edge that is not there, which could cross others.
          closed = false;
          break;
        }
        if (best == start) break;
        used_[best] = 1;
        e = best;
      }
      if (closed) {
        walks.starts.push_back(walks.points.size());
      } else {
        walks.points.resize(walks.starts.back());
        walks.ids.resize(walks.starts.back());
      }
    }
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  const std::vector<DirectedEdge>& edges_;
  std::size_t point_count_;
  std::vector<std::size_t>& first_;
  std::vector<std::size_t>& leaving_;
  std::vector<char>& used_;
};

// Splits closed walk k at every repeated vertex into closed walks without repeats.
// `position` is indexed by point id, kNotOnStack for every id on entry and on exit.
void split_at_repeats(const Walks& walks, std::size_t k, std::vector<std::size_t>& position,
                      std::vector<std::size_t>& stack_ids, std::vector<Loop2>& out) {
  Loop2 stack;
  stack.reserve(walks.starts[k + 1] - walks.starts[k]);
  stack_ids.clear();
  for (std::size_t i = walks.starts[k]; i < walks.starts[k + 1]; ++i) {
    const Point2& p = walks.points[i];
    const std::size_t id = walks.ids[i];
    if (position[id] == kNotOnStack) {
      position[id] = stack.size();
      stack.push_back(p);
      stack_ids.push_back(id);
      continue;
    }
    // p closes the stretch stack[position .. end]: emit it as its own loop.
    const std::size_t from = position[id];
    Loop2 piece(stack.begin() + static_cast<std::ptrdiff_t>(from), stack.end());
    for (std::size_t j = from + 1; j < stack.size(); ++j) position[stack_ids[j]] = kNotOnStack;
    stack.resize(from + 1);
    stack_ids.resize(from + 1);
    out.push_back(std::move(piece));
  }
  for (const std::size_t id : stack_ids) position[id] = kNotOnStack;
  out.push_back(std::move(stack));
}

// Whether hole lies inside outer: decided at a vertex of the hole off outer's boundary
// (a hole may touch its outer loop at points, never along an edge).
bool encloses(const Loop2& outer, const Loop2& hole) {
  for (const Point2& p : hole) {
    const Location where = locate(p, outer);
    if (where != Location::kBoundary) return where == Location::kInside;
  }
  for (std::size_t i = 0; i < hole.size(); ++i) {
    const Point2& a = hole[i];
    const Point2& b = hole[(i + 1) % hole.size()];
    const Location where = locate_midpoint(a, b, outer);
    if (where != Location::kBoundary) return where == Location::kInside;
  }
  return false;
}

// A counter-clockwise loop inside another one overlaps it, which exact arithmetic never
// gives: it is a hole so thin that rounding its crossing points turned it over (a sliver
// cut out of a region). Within the rounding bound it is that artefact and is dropped, so
// the region keeps the sliver's area, an error within the bound; a larger one stays.
void drop_turned_over_holes(PolygonSet2& polygons) {
  if (polygons.size() < 2) return;
  std::vector<std::size_t> drop;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const Loop2& loop = polygons[i].outer;
    if (std::fabs(signed_area(loop)) > rounding_area_bound(loop)) continue;
    const Box2 b = box_of(loop);
    for (std::size_t j = 0; j < polygons.size(); ++j) {
      if (j == i || !box_of(polygons[j].outer).contains(b)) continue;
      if (encloses(polygons[j].outer, loop)) {
        drop.push_back(i);
        break;
      }
    }
  }
  for (auto it = drop.rbegin(); it != drop.rend(); ++it) {
    polygons.erase(polygons.begin() + static_cast<std::ptrdiff_t>(*it));
  }
}

}  // namespace

PolygonSet2 assemble_polygons(const std::vector<DirectedEdge>& edges, std::size_t point_count) {
  std::vector<Loop2> loops;
  {
    thread_local TraceWorkspace workspace;
    Tracer tracer(edges, point_count, workspace);
    Walks& walks = workspace.walks;
    tracer.trace(walks);
    std::vector<std::size_t>& position = workspace.position;
    position.assign(tracer.point_count(), kNotOnStack);
    loops.reserve(walks.starts.size() - 1);
    for (std::size_t k = 0; k + 1 < walks.starts.size(); ++k) {
      split_at_repeats(walks, k, position, workspace.stack_ids, loops);
    }
    if (edges.size() > kKeptEdges) workspace = TraceWorkspace{};
  }

  PolygonSet2 polygons;
  std::vector<Loop2> holes;
  for (Loop2& loop : loops) {
    if (!remove_spikes(loop)) continue;
    if (is_counter_clockwise(loop)) {
      polygons.push_back({std::move(loop), {}});
    } else {
      holes.push_back(std::move(loop));
    }
  }
  drop_turned_over_holes(polygons);
  if (holes.empty()) return polygons;

  std::vector<Box2> outer_bounds;
  std::vector<double> outer_areas;
  for (const PolygonWithHoles2& p : polygons) {
    outer_bounds.push_back(box_of(p.outer));
    outer_areas.push_back(signed_area(p.outer));
  }
  std::vector<Loop2> orphans;
  for (Loop2& hole : holes) {
    const Box2 hb = box_of(hole);
    std::size_t parent = polygons.size();
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      if (!outer_bounds[i].contains(hb)) continue;
      if (parent < polygons.size() && outer_areas[i] >= outer_areas[parent]) continue;
      if (encloses(polygons[i].outer, hole)) parent = i;
    }
    if (parent == polygons.size()) {
      orphans.push_back(std::move(hole));
    } else {
      polygons[parent].holes.push_back(std::move(hole));
    }
  }
  // A clockwise loop inside no outer loop cannot come from exact arithmetic: it is a
  // sliver whose orientation the rounding of crossing points turned over. If its area is
  // within the construction error bound (clip.h) it is that artefact and is dropped;
  // anything larger keeps its area as an outer loop.
  for (Loop2& loop : orphans) {
    if (std::fabs(signed_area(loop)) <= rounding_area_bound(loop)) continue;
    std::reverse(loop.begin(), loop.end());
    polygons.push_back({std::move(loop), {}});
  }
  return polygons;
}

}  // namespace shadowgen::clipper::detail
