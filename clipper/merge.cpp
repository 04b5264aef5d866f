#include "clipper/merge.h"

#include <unordered_map>

#include "clipper/detail/boundary_graph.h"
#include "clipper/detail/snap_rounding.h"
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
  // Snapped together (detail/snap_rounding.h), the pieces' boundaries meet only at
  // common vertices: T-junctions, and seams whose vertices were rounded on either side of
  // the common line, become runs of segments shared exactly, which cancel below.
  std::vector<Loop2> loops[2];
  for (const PolygonWithHoles2& p : normalized(PolygonSet2(polygons.begin(), polygons.end()))) {
    loops[0].push_back(p.outer);
    for (const Loop2& h : p.holes) loops[0].push_back(h);
  }
  detail::snap_round(loops);
  // Count each directed edge; a reversed copy cancels one.
  std::unordered_map<EdgeKey, int, EdgeKeyHash> count;
  for (const Loop2& loop : loops[0]) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& a = loop[i];
      const Point2& b = loop[(i + 1) % loop.size()];
      if (a == b) continue;
      const auto reverse = count.find({b, a});
      if (reverse != count.end() && reverse->second > 0) {
        --reverse->second;
      } else {
        ++count[{a, b}];
      }
    }
  }
  std::vector<detail::DirectedEdge> edges;
  edges.reserve(count.size());
  // Emitted in input order so the result does not depend on hash-table order.
  for (const Loop2& loop : loops[0]) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& a = loop[i];
      const Point2& b = loop[(i + 1) % loop.size()];
      const auto it = count.find({a, b});
      if (it != count.end() && it->second > 0) {
        --it->second;
        edges.push_back({a, b});
      }
    }
  }
  return detail::assemble_polygons(edges);
}

}  // namespace shadowgen::clipper
