// The overlay's classification: the graph built (overlay_graph.h), its windings spread
// (overlay_windings.h), and each edge kept where the regions on its two sides differ.

#include "overlay.h"

#include "overlay_graph.h"
#include "overlay_windings.h"

namespace shadowgen::clipper::detail {
namespace {

// Overlays of more points than this give their storage back when done, so that a thread
// does not hold a huge ground's graph for good.
constexpr std::size_t kKeptPoints = std::size_t{1} << 14;

OverlayEdges combine(const OverlayGraph& g) {
  auto in_both = [](const Winding& w) { return w[0] > 0 && w[1] > 0; };
  auto in_subject_only = [](const Winding& w) { return w[0] > 0 && w[1] <= 0; };
  OverlayEdges out;
  out.point_count = g.index.size();
  out.inside.reserve(g.edges.size());
  out.outside.reserve(g.edges.size());
  for (const OverlayEdge& e : g.edges) {
    const Winding right = e.right, left = e.right + e.multiplicity;
    const Point2& lo = g.index.point(e.lo);
    const Point2& hi = g.index.point(e.hi);
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
  thread_local OverlayGraph graph;
  build_overlay_graph(loops, graph);
  spread_windings(loops, graph);
  OverlayEdges out = combine(graph);
  if (graph.index.size() > kKeptPoints) graph = OverlayGraph{};
  return out;
}

}  // namespace shadowgen::clipper::detail
