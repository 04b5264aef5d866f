#include "clipper/detail/vertex_merge.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "clipper/detail/snap.h"

namespace shadowgen::clipper::detail {
namespace {

bool close(const Point2& a, const Point2& b) {
  return std::hypot(a.x - b.x, a.y - b.y) <= snap_distance(a, b);
}

// Every close pair of distinct points, each pair once. A point q at distance d from p is
// close only if d <= 2·(4u·d + u·max|coordinate|), so d < 4u·(|p.x| + |p.y| + d) <
// 8u·(|p.x| + |p.y|): a window in x of that half-width around p holds every such q.
std::vector<std::pair<Point2, Point2>> close_pairs(std::vector<Point2> points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::vector<std::pair<Point2, Point2>> pairs;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point2& p = points[i];
    const double half = 8.0 * 0x1p-53 * (std::fabs(p.x) + std::fabs(p.y));
    for (std::size_t j = i + 1; j < points.size() && points[j].x <= p.x + half; ++j) {
      if (close(p, points[j])) pairs.emplace_back(p, points[j]);
    }
  }
  return pairs;
}

}  // namespace

std::vector<DirectedEdge> merge_close_vertices(std::vector<DirectedEdge> edges,
                                               const std::function<bool(const Point2&)>& is_input,
                                               std::unordered_set<Point2, Point2Hash>& moved) {
  std::vector<Point2> vertices;
  vertices.reserve(2 * edges.size());
  for (const DirectedEdge& e : edges) {
    vertices.push_back(e.from);
    vertices.push_back(e.to);
  }
  const std::vector<std::pair<Point2, Point2>> pairs = close_pairs(std::move(vertices));
  if (pairs.empty()) return edges;

  // Per constructed vertex, where it goes: an input vertex is exact, so the nearest close
  // one wins; among constructed ones only, the least.
  struct Choice {
    Point2 to;
    bool input = false;
    double distance = INFINITY;
  };
  std::unordered_map<Point2, Choice, Point2Hash> choice;
  std::unordered_map<Point2, bool, Point2Hash> input;
  auto input_vertex = [&](const Point2& p) {
    const auto [it, fresh] = input.try_emplace(p, false);
    if (fresh) it->second = is_input(p);
    return it->second;
  };
  auto offer = [&](const Point2& from, const Point2& to) {
    if (input_vertex(from)) return;
    const bool to_input = input_vertex(to);
    if (!to_input && !(to < from)) return;
    const double d = std::hypot(to.x - from.x, to.y - from.y);
    auto [it, fresh] = choice.try_emplace(from, Choice{to, to_input, d});
    if (fresh) return;
    Choice& c = it->second;
    const bool better = to_input != c.input ? to_input
                        : to_input          ? d < c.distance || (d == c.distance && to < c.to)
                                            : to < c.to;
    if (better) c = {to, to_input, d};
  };
  for (const auto& [p, q] : pairs) {
    offer(p, q);
    offer(q, p);
  }
  if (choice.empty()) return edges;

  // Follow chains (a constructed point merged into one merged into a vertex) to their
  // end; each step goes to an input vertex or to a lesser point, so chains end.
  auto resolve = [&choice](Point2 p) {
    for (auto it = choice.find(p); it != choice.end(); it = choice.find(p)) p = it->second.to;
    return p;
  };
  std::vector<DirectedEdge> out;
  out.reserve(edges.size());
  for (const DirectedEdge& e : edges) {
    const Point2 from = resolve(e.from), to = resolve(e.to);
    if (from == to) continue;
    if (from != e.from) moved.insert(from);
    if (to != e.to) moved.insert(to);
    out.push_back({from, to});
  }
  return out;
}

}  // namespace shadowgen::clipper::detail
