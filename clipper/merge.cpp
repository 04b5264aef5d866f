#include "clipper/merge.h"

#include <unordered_map>

#include "clipper/detail/boundary_graph.h"
#include "clipper/detail/edge_noding.h"
#include "clipper/normalize.h"

namespace shadowgen::clipper {
namespace {

struct EdgeKey {
  Point2 from;
  Point2 to;
  friend bool operator==(const EdgeKey&, const EdgeKey&) = default;
};

struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& e) const noexcept {
    const Point2Hash h;
    return h(e.from) * 31u + h(e.to);
  }
};

}  // namespace

PolygonSet2 merge_adjacent(std::span<const PolygonWithHoles2> polygons) {
  if (polygons.size() <= 1) return normalized(PolygonSet2(polygons.begin(), polygons.end()));
  const PolygonSet2 input = normalized(PolygonSet2(polygons.begin(), polygons.end()));
  // Count each directed edge; a reversed copy cancels one.
  std::unordered_map<EdgeKey, int, EdgeKeyHash> count;
  auto add_loop = [&count](const Loop2& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& a = loop[i];
      const Point2& b = loop[(i + 1) % loop.size()];
      const auto reverse = count.find({b, a});
      if (reverse != count.end() && reverse->second > 0) {
        --reverse->second;
      } else {
        ++count[{a, b}];
      }
    }
  };
  for (const PolygonWithHoles2& p : input) {
    add_loop(p.outer);
    for (const Loop2& h : p.holes) add_loop(h);
  }
  std::vector<detail::DirectedEdge> edges;
  edges.reserve(count.size());
  // Emit in input order so the result does not depend on hash-table order.
  auto emit_loop = [&](const Loop2& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& a = loop[i];
      const Point2& b = loop[(i + 1) % loop.size()];
      const auto it = count.find({a, b});
      if (it != count.end() && it->second > 0) {
        --it->second;
        edges.push_back({a, b});
      }
    }
  };
  for (const PolygonWithHoles2& p : input) {
    emit_loop(p.outer);
    for (const Loop2& h : p.holes) emit_loop(h);
  }
  // What is left may still meet at T-junctions (a vertex of one piece on an edge of
  // another, or within a rounding of it): split there, the overlapping stretches cancel
  // too.
  return detail::assemble_polygons(detail::snap_vertices_onto_edges(std::move(edges)));
}

}  // namespace shadowgen::clipper
