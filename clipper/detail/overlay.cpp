#include "overlay.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "clipper/box.h"
#include "clipper/predicates.h"
#include "point_index.h"
#include "point_location.h"

namespace shadowgen::clipper::detail {
namespace {

using Boundary = std::vector<Loop2>;
using Winding = std::array<int, 2>;  // the subject's, the clip's

Winding operator+(const Winding& a, const Winding& b) { return {a[0] + b[0], a[1] + b[1]}; }
Winding operator-(const Winding& a, const Winding& b) { return {a[0] - b[0], a[1] - b[1]}; }

// A segment of the graph, run from its lower id to its higher.
struct Edge {
  std::uint32_t lo, hi;
  Winding multiplicity{};  // net runs lo -> hi, per operand
  Winding right{};         // winding numbers of the faces on its right
  bool known = false;
};

// Where the direction v -> a comes counter-clockwise from the x axis: 0 for [0°, 180°),
// 1 for [180°, 360°). Comparing doubles is exact, so this is too.
int half_plane(const Point2& v, const Point2& a) {
  return (a.y < v.y || (a.y == v.y && a.x < v.x)) ? 1 : 0;
}

// A segment's run, lo -> hi or back, in one operand's loops.
struct EdgeRun {
  std::uint32_t hi;
  int operand;
  int sign;  // +1 for lo -> hi
};

// The storage of one overlay, kept per thread from call to call: the graph is built anew
// for every clip, and a clip of small polygons (a few dozen points) would otherwise spend
// much of its time allocating it.
struct Workspace {
  PointIndex index{0};
  std::vector<std::vector<std::uint32_t>> ids[2];  // per operand, loop: its points' ids
  std::vector<Edge> edges;
  std::vector<std::uint32_t> first, incidence, part;
  // Scratch of the steps that build those.
  std::vector<EdgeRun> runs;
  std::vector<std::uint32_t> run_first, fill, seeds, stack, todo;
  std::vector<char> done;
};

// Overlays of more points than this give their storage back when done, so that a thread
// does not hold a huge ground's graph for good.
constexpr std::size_t kKeptPoints = std::size_t{1} << 14;

class Graph {
 public:
  Graph(const Boundary (&loops)[2], Workspace& workspace);

  OverlayEdges combine() const;

 private:
  void collect_edges();
  void collect_incidence();
  void spread_windings();
  std::vector<Winding> windings_outside_parts(const std::vector<std::uint32_t>& seeds) const;
  void spread_part(std::uint32_t seed, const Winding& outside);
  void spread_around(std::uint32_t v, std::uint32_t from_edge, std::vector<std::uint32_t>& todo);

  std::span<std::uint32_t> edges_at(std::uint32_t v) {
    return {incidence_.data() + first_[v], first_[v + 1] - first_[v]};
  }
  std::uint32_t far_end(const Edge& e, std::uint32_t v) const { return e.lo == v ? e.hi : e.lo; }
  // The multiplicities of e run away from v, and the windings on its left so run.
  Winding outward_multiplicity(const Edge& e, std::uint32_t v) const {
    return e.lo == v ? e.multiplicity : Winding{} - e.multiplicity;
  }
  Winding left_of_outward(const Edge& e, std::uint32_t v) const {
    return e.lo == v ? e.right + e.multiplicity : e.right;
  }

  const Boundary (&loops_)[2];
  Workspace& w_;
  PointIndex& index_;
  std::vector<std::vector<std::uint32_t>> (&ids_)[2];
  std::vector<Edge>& edges_;
  std::vector<std::uint32_t>& first_;      // per vertex: its slice of incidence_
  std::vector<std::uint32_t>& incidence_;  // edge indices, counter-clockwise around each vertex
  std::vector<std::uint32_t>& part_;       // per vertex: its connected part
};

std::size_t point_count(const Boundary (&loops)[2]) {
  std::size_t n = 0;
  for (const Boundary& b : loops) {
    for (const Loop2& l : b) n += l.size();
  }
  return n;
}

Graph::Graph(const Boundary (&loops)[2], Workspace& workspace)
    : loops_(loops),
      w_(workspace),
      index_(workspace.index),
      ids_(workspace.ids),
      edges_(workspace.edges),
      first_(workspace.first),
      incidence_(workspace.incidence),
      part_(workspace.part) {
  index_.reset(point_count(loops));
  edges_.clear();
  for (int s = 0; s < 2; ++s) {
    ids_[s].resize(loops[s].size());
    for (std::size_t l = 0; l < loops[s].size(); ++l) {
      ids_[s][l].clear();
      ids_[s][l].reserve(loops[s][l].size());
      for (const Point2& p : loops[s][l]) {
        ids_[s][l].push_back(static_cast<std::uint32_t>(index_.id(p)));
      }
    }
  }
  collect_edges();
  collect_incidence();
  spread_windings();
}

// Every distinct segment once, with each operand's net multiplicity along it: the loops'
// edges bucketed by their lower end (a counting sort), then merged within each bucket.
void Graph::collect_edges() {
  using Run = EdgeRun;
  const std::size_t count = index_.size();
  std::vector<std::uint32_t>& first = w_.run_first;
  first.assign(count + 1, 0);
  auto each_run = [&](auto&& visit) {
    for (int s = 0; s < 2; ++s) {
      for (const std::vector<std::uint32_t>& ids : ids_[s]) {
        const std::size_t n = ids.size();
        for (std::size_t i = 0; i < n; ++i) {
          const std::uint32_t a = ids[i], b = ids[i + 1 == n ? 0 : i + 1];
          if (a == b) continue;
          visit(std::min(a, b), Run{std::max(a, b), s, a < b ? 1 : -1});
        }
      }
    }
  };
  each_run([&first](std::uint32_t lo, const Run&) { ++first[lo + 1]; });
  for (std::size_t v = 0; v < count; ++v) first[v + 1] += first[v];
  std::vector<Run>& runs = w_.runs;
  runs.resize(first.back());
  std::vector<std::uint32_t>& fill = w_.fill;
  fill.assign(first.begin(), first.end() - 1);
  each_run([&](std::uint32_t lo, const Run& r) { runs[fill[lo]++] = r; });
  edges_.reserve(runs.size());
  for (std::uint32_t lo = 0; lo < count; ++lo) {
    const auto begin = runs.begin() + first[lo], end = runs.begin() + first[lo + 1];
    std::sort(begin, end, [](const Run& a, const Run& b) { return a.hi < b.hi; });
    for (auto r = begin; r != end; ++r) {
      if (r == begin || r->hi != (r - 1)->hi) {
        // Made in place: a temporary Edge copied in cost a stalled load per edge.
        Edge& e = edges_.emplace_back();
        e.lo = lo;
        e.hi = r->hi;
      }
      edges_.back().multiplicity[r->operand] += r->sign;
    }
  }
}

// Each vertex's edges, in counter-clockwise order around it (exact: the half plane of
// the direction, then orient2d; two edges of one vertex never run the same way in a
// noded graph).
void Graph::collect_incidence() {
  const std::size_t count = index_.size();
  first_.assign(count + 1, 0);
  for (const Edge& e : edges_) {
    ++first_[e.lo + 1];
    ++first_[e.hi + 1];
  }
  for (std::size_t v = 0; v < count; ++v) first_[v + 1] += first_[v];
  incidence_.resize(first_.back());
  std::vector<std::uint32_t>& fill = w_.fill;
  fill.assign(first_.begin(), first_.end() - 1);
  for (std::uint32_t i = 0; i < edges_.size(); ++i) {
    incidence_[fill[edges_[i].lo]++] = i;
    incidence_[fill[edges_[i].hi]++] = i;
  }
  for (std::uint32_t v = 0; v < count; ++v) {
    const std::span<std::uint32_t> at = edges_at(v);
    if (at.size() <= 2) continue;  // any order is counter-clockwise
    const Point2& p = index_.point(v);
    std::sort(at.begin(), at.end(), [&](std::uint32_t a, std::uint32_t b) {
      const Point2& pa = index_.point(far_end(edges_[a], v));
      const Point2& pb = index_.point(far_end(edges_[b], v));
      const int ha = half_plane(p, pa), hb = half_plane(p, pb);
      if (ha != hb) return ha < hb;
      return orient2d(p, pa, pb) == Orientation::kCounterClockwise;
    });
  }
}

// The windings of the sectors around v, from those left of the edge from_edge: turning
// counter-clockwise, each next edge is crossed from its right to its left.
void Graph::spread_around(std::uint32_t v, std::uint32_t from_edge,
                          std::vector<std::uint32_t>& todo) {
  const std::span<std::uint32_t> at = edges_at(v);
  const std::size_t k = at.size();
  const std::size_t start =
      static_cast<std::size_t>(std::find(at.begin(), at.end(), from_edge) - at.begin());
  Winding left = left_of_outward(edges_[from_edge], v);
  std::size_t next = start;
  for (std::size_t step = 1; step < k; ++step) {
    next = next + 1 == k ? 0 : next + 1;
    Edge& e = edges_[at[next]];
    left = left + outward_multiplicity(e, v);
    if (e.known) continue;
    e.right = e.lo == v ? left - e.multiplicity : left;
    e.known = true;
    todo.push_back(far_end(e, v));
    todo.push_back(at[next]);
  }
}

// The winding numbers of the other parts' loops around each part's seed (which lies on
// none of them: parts share no vertex and, the graph being noded, no point). A loop winds
// around no point outside its box, so the seeds are swept in x order past the loops
// whose boxes span their x: about the square root of the loops at a time for blocks
// spread over a ground, where testing every loop for every seed grew with the square of
// the parts. Winding numbers are sums of integers: the order changes nothing.
std::vector<Winding> Graph::windings_outside_parts(const std::vector<std::uint32_t>& seeds) const {
  struct LoopRef {
    Box2 box;
    std::uint32_t part;
    int operand;
    std::uint32_t loop;
  };
  std::vector<LoopRef> loops;
  for (int s = 0; s < 2; ++s) {
    for (std::size_t l = 0; l < loops_[s].size(); ++l) {
      if (ids_[s][l].empty()) continue;
      loops.push_back(
          {box_of(loops_[s][l]), part_[ids_[s][l].front()], s, static_cast<std::uint32_t>(l)});
    }
  }
  std::sort(loops.begin(), loops.end(),
            [](const LoopRef& a, const LoopRef& b) { return a.box.xmin < b.box.xmin; });
  std::vector<std::uint32_t> order(seeds.size());
  for (std::uint32_t part = 0; part < seeds.size(); ++part) order[part] = part;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return index_.point(seeds[a]).x < index_.point(seeds[b]).x;
  });
  std::vector<Winding> out(seeds.size(), Winding{});
  std::vector<const LoopRef*> active;
  std::size_t next = 0;
  for (const std::uint32_t part : order) {
    const Point2& p = index_.point(seeds[part]);
    for (; next < loops.size() && loops[next].box.xmin <= p.x; ++next) {
      active.push_back(&loops[next]);
    }
    std::size_t kept = 0;
    for (const LoopRef* loop : active) {
      if (loop->box.xmax < p.x) continue;  // left behind: the seeds come in x order
      active[kept++] = loop;
      if (loop->part == part || !loop->box.contains(p)) continue;
      add_winding_number(p, loops_[loop->operand][loop->loop], out[part][loop->operand]);
    }
    active.resize(kept);
  }
  return out;
}

// Spreads the windings over the part of `seed`, its lowest-leftmost vertex, whose
// outside (the sector straight left of it) has the windings `outside`.
void Graph::spread_part(std::uint32_t seed, const Winding& outside) {
  const std::span<std::uint32_t> at = edges_at(seed);
  if (at.empty()) return;
  // Every edge of the seed runs to the right of it, or straight up: the sector left of
  // the one turned furthest counter-clockwise contains the direction straight left,
  // outside all of the part's loops.
  const Point2& p = index_.point(seed);
  std::uint32_t top = at.front();
  for (const std::uint32_t e : at) {
    if (orient2d(p, index_.point(far_end(edges_[top], seed)),
                 index_.point(far_end(edges_[e], seed))) == Orientation::kCounterClockwise) {
      top = e;
    }
  }
  Edge& first = edges_[top];
  first.right = first.lo == seed ? outside - first.multiplicity : outside;
  first.known = true;
  std::vector<char>& done = w_.done;
  std::vector<std::uint32_t>& todo = w_.todo;  // pairs: a vertex, and an edge known
  todo.assign({seed, top, far_end(first, seed), top});
  while (!todo.empty()) {
    const std::uint32_t e = todo.back();
    todo.pop_back();
    const std::uint32_t v = todo.back();
    todo.pop_back();
    if (done[v]) continue;
    done[v] = 1;
    spread_around(v, e, todo);
  }
}

void Graph::spread_windings() {
  const std::size_t count = index_.size();
  std::vector<char>& done = w_.done;
  done.assign(count, 0);
  if (count == 0) return;
  // Most overlays are one connected part. The lowest-leftmost vertex of all lies outside
  // every loop, so the spreading starts there with no winding; only where it leaves
  // vertices unreached are the parts found and located against each other. (Where two
  // distinct points compare equal, a zero of either sign, the parts are found too, as
  // they pick their seeds.)
  std::uint32_t lowest = 0;
  bool tie = false;
  for (std::uint32_t v = 1; v < count; ++v) {
    const Point2& p = index_.point(v);
    const Point2& q = index_.point(lowest);
    if (p < q) {
      lowest = v;
      tie = false;
    } else if (!(q < p)) {
      tie = true;
    }
  }
  if (!tie) {
    spread_part(lowest, Winding{});
    if (std::find(done.begin(), done.end(), 0) == done.end()) return;
    for (Edge& e : edges_) e.known = false;
    done.assign(count, 0);
  }

  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  part_.assign(count, kNone);
  // The connected parts, each with its lowest-leftmost vertex.
  std::vector<std::uint32_t>& seeds = w_.seeds;
  std::vector<std::uint32_t>& stack = w_.stack;
  seeds.clear();
  for (std::uint32_t v = 0; v < count; ++v) {
    if (part_[v] != kNone) continue;
    const auto part = static_cast<std::uint32_t>(seeds.size());
    std::uint32_t seed = v;
    part_[v] = part;
    stack.assign(1, v);
    while (!stack.empty()) {
      const std::uint32_t u = stack.back();
      stack.pop_back();
      const Point2& pu = index_.point(u);
      const Point2& ps = index_.point(seed);
      if (pu.x < ps.x || (pu.x == ps.x && pu.y < ps.y)) seed = u;
      for (const std::uint32_t e : edges_at(u)) {
        const std::uint32_t w = far_end(edges_[e], u);
        if (part_[w] == kNone) {
          part_[w] = part;
          stack.push_back(w);
        }
      }
    }
    seeds.push_back(seed);
  }
  // Parts are located against each other.
  const std::vector<Winding> outside =
      seeds.size() > 1 ? windings_outside_parts(seeds) : std::vector<Winding>(seeds.size());
  for (std::uint32_t part = 0; part < seeds.size(); ++part) spread_part(seeds[part], outside[part]);
}

OverlayEdges Graph::combine() const {
  auto in_both = [](const Winding& w) { return w[0] > 0 && w[1] > 0; };
  auto in_subject_only = [](const Winding& w) { return w[0] > 0 && w[1] <= 0; };
  OverlayEdges out;
  out.point_count = index_.size();
  out.inside.reserve(edges_.size());
  out.outside.reserve(edges_.size());
  for (const Edge& e : edges_) {
    const Winding right = e.right, left = e.right + e.multiplicity;
    const Point2& lo = index_.point(e.lo);
    const Point2& hi = index_.point(e.hi);
    if (in_both(left) != in_both(right)) {
      out.inside.push_back(in_both(left) ? DirectedEdge{lo, hi, e.lo, e.hi}
                                         : DirectedEdge{hi, lo, e.hi, e.lo});
    }
    if (in_subject_only(left) != in_subject_only(right)) {
      out.outside.push_back(in_subject_only(left) ? DirectedEdge{lo, hi, e.lo, e.hi}
                                                  : DirectedEdge{hi, lo, e.hi, e.lo});
    }
  }
  return out;
}

}  // namespace

OverlayEdges overlay(const std::vector<Loop2> (&loops)[2]) {
  thread_local Workspace workspace;
  OverlayEdges out = Graph(loops, workspace).combine();
  if (workspace.index.size() > kKeptPoints) workspace = Workspace{};
  return out;
}

}  // namespace shadowgen::clipper::detail
