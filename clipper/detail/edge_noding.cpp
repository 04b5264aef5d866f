#include "clipper/detail/edge_noding.h"

#include <algorithm>
#include <cmath>

#include "clipper/detail/crossing.h"
#include "clipper/detail/snap.h"
#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {
namespace {

// Rounds after which noding stops. Each round works only near the points the previous
// one constructed; a rounded crossing that makes a new contact is rare, one that makes
// a contact again in the next round was never seen. The bound keeps the cost finite on
// adversarial input; the assembly copes with what is left (clip.h's contract).
constexpr int kMaxRounds = 8;

using PointSet = std::unordered_set<Point2, Point2Hash>;

struct Splits {
  std::vector<std::vector<Point2>> at;  // per edge, the points to split it at
  PointSet constructed;                 // crossing points made in this round
  std::size_t count = 0;

  void add(std::size_t edge, const Point2& p, const DirectedEdge& e) {
    if (p == e.from || p == e.to) return;
    at[edge].push_back(p);
    ++count;
  }
};

// Every contact of edges i and j other than a shared endpoint.
void contact(const std::vector<DirectedEdge>& edges, std::size_t i, std::size_t j, Splits& splits) {
  const DirectedEdge& a = edges[i];
  const DirectedEdge& b = edges[j];
  // Edges of one loop share endpoints: they cannot cross, only overlap along a line. Their
  // shared end is collinear by definition, so it is not asked (an exact zero is the slow
  // path of orient2d).
  const bool shares = a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to;
  if (shares) {
    const bool a_from_shared = a.from == b.from || a.from == b.to;
    const bool b_from_shared = b.from == a.from || b.from == a.to;
    const Point2& a_other = a_from_shared ? a.to : a.from;
    const Point2& b_other = b_from_shared ? b.to : b.from;
    if (a_other == b_other) return;  // the same segment: cancellation's business
    if (orient2d(a.from, a.to, b_other) == Orientation::kCollinear &&
        on_segment(a.from, a.to, b_other)) {
      splits.add(i, b_other, a);
    }
    if (orient2d(b.from, b.to, a_other) == Orientation::kCollinear &&
        on_segment(b.from, b.to, a_other)) {
      splits.add(j, a_other, b);
    }
    return;
  }
  const Orientation oa0 = orient2d(b.from, b.to, a.from);
  const Orientation oa1 = orient2d(b.from, b.to, a.to);
  if (oa0 == oa1 && oa0 != Orientation::kCollinear) return;
  const Orientation ob0 = orient2d(a.from, a.to, b.from);
  const Orientation ob1 = orient2d(a.from, a.to, b.to);
  if (ob0 == ob1 && ob0 != Orientation::kCollinear) return;
  if (oa0 != Orientation::kCollinear && oa1 != Orientation::kCollinear &&
      ob0 != Orientation::kCollinear && ob1 != Orientation::kCollinear) {
    const Point2 p = crossing_point(a.from, a.to, b.from, b.to);
    splits.constructed.insert(p);
    splits.add(i, p, a);
    splits.add(j, p, b);
    return;
  }
  // An endpoint of one lying on the other: exact, it splits the other where it is.
  if (oa0 == Orientation::kCollinear && on_segment(b.from, b.to, a.from)) splits.add(j, a.from, b);
  if (oa1 == Orientation::kCollinear && on_segment(b.from, b.to, a.to)) splits.add(j, a.to, b);
  if (ob0 == Orientation::kCollinear && on_segment(a.from, a.to, b.from)) splits.add(i, b.from, a);
  if (ob1 == Orientation::kCollinear && on_segment(a.from, a.to, b.to)) splits.add(i, b.to, a);
}

// One sweep over x calling visit(i, j) for every pair of edges whose boxes, each grown
// by margin(edge) and kept only where select(edge), overlap.
template <typename Margin, typename Select, typename Visit>
void for_each_close_pair(const std::vector<DirectedEdge>& edges, Margin margin, Select select,
                         Visit visit) {
  struct Item {
    double xmin, xmax, ymin, ymax;
    std::size_t edge;
    bool selected;
  };
  std::vector<Item> items;
  items.reserve(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const DirectedEdge& e = edges[i];
    const double d = margin(e);
    items.push_back({std::min(e.from.x, e.to.x) - d, std::max(e.from.x, e.to.x) + d,
                     std::min(e.from.y, e.to.y) - d, std::max(e.from.y, e.to.y) + d, i, select(e)});
  }
  std::sort(items.begin(), items.end(),
            [](const Item& a, const Item& b) { return a.xmin < b.xmin; });
  std::vector<const Item*> active;
  for (const Item& item : items) {
    std::size_t kept = 0;
    for (const Item* c : active) {
      // Kept unless left behind by the sweep (without branches: unpredictable).
      active[kept] = c;
      const bool live = c->xmax >= item.xmin;
      kept += live ? 1 : 0;
      if (live & (item.selected | c->selected) & (c->ymin <= item.ymax) & (item.ymin <= c->ymax)) {
        visit(c->edge, item.edge);
      }
    }
    active.resize(kept);
    active.push_back(&item);
  }
}

// Every contact between edges of which at least one has an endpoint in `moved`.
Splits find_contacts(const std::vector<DirectedEdge>& edges, const PointSet& moved) {
  Splits splits;
  splits.at.resize(edges.size());
  for_each_close_pair(
      edges, [](const DirectedEdge&) { return 0.0; },
      [&moved](const DirectedEdge& e) { return moved.contains(e.from) || moved.contains(e.to); },
      [&](std::size_t i, std::size_t j) { contact(edges, i, j, splits); });
  return splits;
}

// The edges with every split made, points ordered along each edge (crossing.h).
std::vector<DirectedEdge> split_edges(const std::vector<DirectedEdge>& edges, Splits& splits) {
  std::vector<DirectedEdge> out;
  out.reserve(edges.size() + 2 * splits.count);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const DirectedEdge& e = edges[i];
    std::vector<Point2>& points = splits.at[i];
    if (points.empty()) {
      out.push_back(e);
      continue;
    }
    std::sort(points.begin(), points.end(), AlongSegment(e.from, e.to));
    Point2 from = e.from;
    for (const Point2& p : points) {
      if (p == from) continue;
      out.push_back({from, p});
      from = p;
    }
    if (from != e.to) out.push_back({from, e.to});
  }
  return out;
}

// Edges running both ways along the same segment bound nothing: a zero-width strip.
// Found by sorting on the undirected segment (no hashing, one allocation); pairs are
// matched in input order so the result does not depend on the sort.
std::vector<DirectedEdge> without_opposite_pairs(std::vector<DirectedEdge> edges,
                                                 std::size_t& cancelled) {
  struct Key {
    Point2 lo, hi;
    bool forward;  // from == lo
    std::size_t index;
  };
  std::vector<Key> keys;
  keys.reserve(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const DirectedEdge& e = edges[i];
    const bool forward = e.from < e.to;
    keys.push_back({forward ? e.from : e.to, forward ? e.to : e.from, forward, i});
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    if (a.lo != b.lo) return a.lo < b.lo;
    if (a.hi != b.hi) return a.hi < b.hi;
    return a.index < b.index;
  });
  std::vector<bool> removed;
  for (std::size_t g = 0; g < keys.size();) {
    std::size_t end = g + 1;
    while (end < keys.size() && keys[end].lo == keys[g].lo && keys[end].hi == keys[g].hi) ++end;
    if (end - g >= 2) {
      std::vector<std::size_t> ways[2];
      for (std::size_t k = g; k < end; ++k) ways[keys[k].forward ? 1 : 0].push_back(keys[k].index);
      const std::size_t pairs = std::min(ways[0].size(), ways[1].size());
      if (pairs > 0 && removed.empty()) removed.assign(edges.size(), false);
      for (std::size_t k = 0; k < pairs; ++k) {
        removed[ways[0][k]] = true;
        removed[ways[1][k]] = true;
      }
      cancelled += 2 * pairs;
    }
    g = end;
  }
  if (removed.empty()) return edges;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!removed[i]) edges[kept++] = edges[i];
  }
  edges.resize(kept);
  return edges;
}

// Rounds of noding: the first over the pairs `first` selects, each later one only near
// the points the previous round constructed.
std::vector<DirectedEdge> node(std::vector<DirectedEdge> edges, const PointSet* first,
                               NodingStats* stats, PointSet* made) {
  NodingStats local;
  PointSet moved;
  const PointSet* selection = first;
  for (int round = 0; round < kMaxRounds; ++round) {
    Splits splits = find_contacts(edges, *selection);
    if (splits.count == 0) break;
    ++local.rounds;
    local.splits += splits.count;
    edges = split_edges(edges, splits);
    if (splits.constructed.empty()) break;  // exact splits only: nothing moved
    if (made != nullptr) made->insert(splits.constructed.begin(), splits.constructed.end());
    moved = std::move(splits.constructed);
    selection = &moved;
  }
  edges = without_opposite_pairs(std::move(edges), local.cancelled);
  if (stats != nullptr) *stats = local;
  return edges;
}

}  // namespace

std::vector<DirectedEdge> node_edges(std::vector<DirectedEdge> edges, const PointSet& constructed,
                                     NodingStats* stats, PointSet* made) {
  if (constructed.empty()) {
    NodingStats local;
    edges = without_opposite_pairs(std::move(edges), local.cancelled);
    if (stats != nullptr) *stats = local;
    return edges;
  }
  return node(std::move(edges), &constructed, stats, made);
}

std::vector<DirectedEdge> snap_vertices_onto_edges(std::vector<DirectedEdge> edges,
                                                   NodingStats* stats, PointSet* snapped) {
  Splits splits;
  splits.at.resize(edges.size());
  auto snap = [&](const Point2& v, std::size_t index) {
    const DirectedEdge& e = edges[index];
    if (!within_snap_distance(v, e.from, e.to)) return;
    splits.add(index, v, e);
    if (snapped != nullptr && orient2d(e.from, e.to, v) != Orientation::kCollinear) {
      snapped->insert(v);
    }
  };
  for_each_close_pair(
      edges, [](const DirectedEdge& e) { return snap_distance(e.from, e.to); },
      [](const DirectedEdge&) { return true; },
      [&](std::size_t i, std::size_t j) {
        snap(edges[j].from, i);
        snap(edges[j].to, i);
        snap(edges[i].from, j);
        snap(edges[i].to, j);
      });
  NodingStats local;
  if (splits.count > 0) {
    local.rounds = 1;
    local.splits = splits.count;
    edges = split_edges(edges, splits);
    edges = without_opposite_pairs(std::move(edges), local.cancelled);
  }
  if (stats != nullptr) *stats = local;
  return edges;
}

}  // namespace shadowgen::clipper::detail
