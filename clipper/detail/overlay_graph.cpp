// The overlay's graph built: the loops' points numbered, their segments merged into
// edges with net multiplicities, and the edges sorted around each vertex.

#include "overlay_graph.h"

#include <algorithm>

#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {
namespace {

using Boundary = std::vector<Loop2>;

// Where the direction v -> a comes counter-clockwise from the x axis: 0 for [0°, 180°),
// 1 for [180°, 360°). Comparing doubles is exact, so this is too.
int half_plane(const Point2& v, const Point2& a) {
  return (a.y < v.y || (a.y == v.y && a.x < v.x)) ? 1 : 0;
}

std::size_t point_count(const Boundary (&loops)[2]) {
  std::size_t n = 0;
  for (const Boundary& b : loops) {
    for (const Loop2& l : b) n += l.size();
  }
  return n;
}

// Every distinct segment once, with each operand's net multiplicity along it: the loops'
// edges bucketed by their lower end (a counting sort), then merged within each bucket.
void collect_edges(OverlayGraph& g) {
  using Run = EdgeRun;
  const std::size_t count = g.index.size();
  std::vector<std::uint32_t>& first = g.run_first;
  first.assign(count + 1, 0);
  auto each_run = [&](auto&& visit) {
    for (int s = 0; s < 2; ++s) {
      for (const std::vector<std::uint32_t>& ids : g.ids[s]) {
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
  std::vector<Run>& runs = g.runs;
  runs.resize(first.back());
  std::vector<std::uint32_t>& fill = g.fill;
  fill.assign(first.begin(), first.end() - 1);
  each_run([&](std::uint32_t lo, const Run& r) { runs[fill[lo]++] = r; });
  std::vector<OverlayEdge>& edges = g.edges;
  edges.reserve(runs.size());
  for (std::uint32_t lo = 0; lo < count; ++lo) {
    const auto begin = runs.begin() + first[lo], end = runs.begin() + first[lo + 1];
    std::sort(begin, end, [](const Run& a, const Run& b) { return a.hi < b.hi; });
    for (auto r = begin; r != end; ++r) {
      if (r == begin || r->hi != (r - 1)->hi) {
        // Made in place: a temporary edge copied in cost a stalled load per edge.
        OverlayEdge& e = edges.emplace_back();
        e.lo = lo;
        e.hi = r->hi;
      }
      edges.back().multiplicity[r->operand] += r->sign;
    }
  }
}

// Each vertex's edges, in counter-clockwise order around it (exact: the half plane of
// the direction, then orient2d; two edges of one vertex never run the same way in a
// noded graph).
void collect_incidence(OverlayGraph& g) {
  const std::size_t count = g.index.size();
  const std::vector<OverlayEdge>& edges = g.edges;
  g.first.assign(count + 1, 0);
  for (const OverlayEdge& e : edges) {
    ++g.first[e.lo + 1];
    ++g.first[e.hi + 1];
  }
  for (std::size_t v = 0; v < count; ++v) g.first[v + 1] += g.first[v];
  g.incidence.resize(g.first.back());
  std::vector<std::uint32_t>& fill = g.fill;
  fill.assign(g.first.begin(), g.first.end() - 1);
  for (std::uint32_t i = 0; i < edges.size(); ++i) {
    g.incidence[fill[edges[i].lo]++] = i;
    g.incidence[fill[edges[i].hi]++] = i;
  }
  for (std::uint32_t v = 0; v < count; ++v) {
    const std::span<std::uint32_t> at = g.edges_at(v);
    if (at.size() <= 2) continue;  // any order is counter-clockwise
    const Point2& p = g.index.point(v);
    std::sort(at.begin(), at.end(), [&](std::uint32_t a, std::uint32_t b) {
      const Point2& pa = g.index.point(far_end(edges[a], v));
      const Point2& pb = g.index.point(far_end(edges[b], v));
      const int ha = half_plane(p, pa), hb = half_plane(p, pb);
      if (ha != hb) return ha < hb;
      return orient2d(p, pa, pb) == Orientation::kCounterClockwise;
    });
  }
}

}  // namespace

void build_overlay_graph(const std::vector<Loop2> (&loops)[2], OverlayGraph& graph) {
  graph.index.reset(point_count(loops));
  graph.edges.clear();
  for (int s = 0; s < 2; ++s) {
    graph.ids[s].resize(loops[s].size());
    for (std::size_t l = 0; l < loops[s].size(); ++l) {
      std::vector<std::uint32_t>& ids = graph.ids[s][l];
      ids.clear();
      ids.reserve(loops[s][l].size());
      for (const Point2& p : loops[s][l]) {
        ids.push_back(static_cast<std::uint32_t>(graph.index.id(p)));
      }
    }
  }
  collect_edges(graph);
  collect_incidence(graph);
}

}  // namespace shadowgen::clipper::detail
