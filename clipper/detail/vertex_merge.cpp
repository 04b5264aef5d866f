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

// Every close pair of an edge endpoint and a candidate (a pair of two candidates once).
// A point q at distance d from v is close by distance only if
// d <= 2·(4u·d + u·max|coordinate|), so d < 2.1u·max(|v.x|, |v.y|), and by the radii only
// if d <= twice the largest radius: a window in x of half-width the larger of
// 16u·(|v.x| + |v.y|) and that around v holds every such q. The candidates are few (the
// constructed points), so they are sorted and searched; the endpoints are not sorted.
std::vector<std::pair<Point2, Point2>> close_pairs(
    const std::vector<DirectedEdge>& edges,
    const std::unordered_set<Point2, Point2Hash>& candidates, const ErrorRadii* radii) {
  std::vector<std::pair<Point2, Point2>> pairs;
  if (candidates.empty()) return pairs;
  std::vector<Point2> sorted(candidates.begin(), candidates.end());
  std::sort(sorted.begin(), sorted.end());
  double largest_radius = 0.0;
  if (radii != nullptr) {
    for (const auto& [p, r] : *radii) largest_radius = std::max(largest_radius, r);
  }
  auto radius = [radii](const Point2& p) {
    if (radii == nullptr) return -1.0;
    const auto it = radii->find(p);
    return it == radii->end() ? -1.0 : it->second;
  };
  auto close_enough = [&](const Point2& v, const Point2& q) {
    if (close(v, q)) return true;
    const double rv = radius(v), rq = radius(q);
    return rv >= 0.0 && rq >= 0.0 && std::hypot(v.x - q.x, v.y - q.y) <= rv + rq;
  };
  auto visit = [&](const Point2& v) {
    const double half =
        std::max(16.0 * 0x1p-53 * (std::fabs(v.x) + std::fabs(v.y)), 2.0 * largest_radius);
    auto it = std::lower_bound(sorted.begin(), sorted.end(), Point2{v.x - half, -INFINITY});
    for (; it != sorted.end() && it->x <= v.x + half; ++it) {
      if (*it == v || !close_enough(v, *it)) continue;
      if (!(v < *it) && candidates.contains(v)) continue;  // met again from the other end
      pairs.emplace_back(v, *it);
    }
  };
  for (const DirectedEdge& e : edges) {
    visit(e.from);
    visit(e.to);
  }
  return pairs;
}

}  // namespace

std::vector<DirectedEdge> merge_close_vertices(
    std::vector<DirectedEdge> edges, const std::unordered_set<Point2, Point2Hash>& candidates,
    const std::function<bool(const Point2&)>& is_input,
    std::unordered_set<Point2, Point2Hash>& moved, const ErrorRadii* radii) {
  const std::vector<std::pair<Point2, Point2>> pairs = close_pairs(edges, candidates, radii);
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
