#include "clipper/detail/overlay.h"

#include <algorithm>
#include <cstdint>
#include <span>

#include "clipper/detail/point_index.h"
#include "clipper/detail/point_location.h"
#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {
namespace {

using Boundary = std::vector<Loop2>;

enum class Side { kInside, kOutside, kSharedSame, kSharedOpposite };

// Both snapped operands as one plane graph: an id for every distinct vertex, and for
// each operand which vertices it has, which of its edges cancel (run both ways along one
// segment: a needle or crack of its region that the snapping closed, bounding nothing),
// and, at the vertices both operands share (the nodes), its live edges there.
class Overlay {
 public:
  explicit Overlay(const Boundary (&loops)[2]) : loops_(loops), index_(expected_points(loops)) {
    for (int s = 0; s < 2; ++s) {
      ids_[s].resize(loops[s].size());
      for (std::size_t l = 0; l < loops[s].size(); ++l) {
        for (const Point2& p : loops[s][l]) ids_[s][l].push_back(index_.id(p));
      }
    }
    const std::size_t count = index_.size();
    for (int s = 0; s < 2; ++s) {
      occurrences_[s].assign(count, 0);
      for (const auto& loop : ids_[s]) {
        for (const std::size_t id : loop) {
          occurrences_[s][id] = static_cast<std::uint8_t>(std::min(occurrences_[s][id] + 1, 2));
        }
      }
    }
    for (int s = 0; s < 2; ++s) cancel_opposite_edges(s);
    for (int s = 0; s < 2; ++s) collect_node_edges(s);
  }

  // The edges of operand s by side of the other operand. Shared stretches are told the
  // same way from either operand.
  ClassifiedEdges classify(int s) const;

 private:
  // An edge of the other operand at a node: the far end, and whether it leaves the node.
  struct Incident {
    Point2 far;
    bool leaves;
  };

  static std::size_t expected_points(const Boundary (&loops)[2]) {
    std::size_t n = 0;
    for (const Boundary& b : loops) {
      for (const Loop2& l : b) n += l.size();
    }
    return n;
  }

  bool is_node(std::size_t id) const {
    return occurrences_[0][id] != 0 && occurrences_[1][id] != 0;
  }

  // Marks the edges of operand s that run both ways along one segment. Such a pair either
  // turns straight back at a vertex (a spike) or joins two vertices that the operand
  // passes through more than once; only those are compared.
  void cancel_opposite_edges(int s) {
    struct Key {
      std::size_t lo, hi;
      bool forward;
      std::size_t loop, index;
    };
    std::vector<Key> keys;
    cancelled_[s].resize(loops_[s].size());
    for (std::size_t l = 0; l < loops_[s].size(); ++l) {
      const std::vector<std::size_t>& ids = ids_[s][l];
      const std::size_t n = ids.size();
      std::vector<char>& cancelled = cancelled_[s][l];
      cancelled.assign(n, 0);
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t a = ids[i], b = ids[(i + 1) % n];
        if (occurrences_[s][a] < 2 || occurrences_[s][b] < 2) continue;
        keys.push_back({std::min(a, b), std::max(a, b), a < b, l, i});
      }
      // Spikes: at a vertex met once, the edges in and out are the same segment.
      for (std::size_t i = 0; i < n && n >= 2; ++i) {
        const std::size_t prev = (i + n - 1) % n, next = (i + 1) % n;
        if (occurrences_[s][ids[i]] == 1 && ids[prev] == ids[next]) {
          cancelled[prev] = 1;
          cancelled[i] = 1;
        }
      }
    }
    if (keys.size() < 2) return;
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
      if (a.lo != b.lo) return a.lo < b.lo;
      if (a.hi != b.hi) return a.hi < b.hi;
      if (a.loop != b.loop) return a.loop < b.loop;
      return a.index < b.index;
    });
    for (std::size_t g = 0; g < keys.size();) {
      std::size_t end = g + 1;
      while (end < keys.size() && keys[end].lo == keys[g].lo && keys[end].hi == keys[g].hi) ++end;
      std::vector<const Key*> ways[2];
      for (std::size_t k = g; k < end; ++k) {
        if (!cancelled_[s][keys[k].loop][keys[k].index]) ways[keys[k].forward].push_back(&keys[k]);
      }
      for (std::size_t k = 0; k < std::min(ways[0].size(), ways[1].size()); ++k) {
        cancelled_[s][ways[0][k]->loop][ways[0][k]->index] = 1;
        cancelled_[s][ways[1][k]->loop][ways[1][k]->index] = 1;
      }
      g = end;
    }
  }

  // For operand s, its live edges at every node, by node id (flat, counting sort).
  void collect_node_edges(int s) {
    std::vector<std::size_t>& first = first_[s];
    first.assign(index_.size() + 1, 0);
    auto each_live_edge_at_node = [&](auto&& visit) {
      for (std::size_t l = 0; l < ids_[s].size(); ++l) {
        const std::vector<std::size_t>& ids = ids_[s][l];
        const std::size_t n = ids.size();
        for (std::size_t i = 0; i < n; ++i) {
          if (cancelled_[s][l][i]) continue;
          const std::size_t a = ids[i], b = ids[(i + 1) % n];
          if (is_node(a)) visit(a, Incident{index_.point(b), true});
          if (is_node(b)) visit(b, Incident{index_.point(a), false});
        }
      }
    };
    each_live_edge_at_node([&first](std::size_t id, const Incident&) { ++first[id + 1]; });
    for (std::size_t v = 0; v + 1 < first.size(); ++v) first[v + 1] += first[v];
    incident_[s].resize(first.back());
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    each_live_edge_at_node(
        [&](std::size_t id, const Incident& e) { incident_[s][fill[id]++] = e; });
  }

  std::span<const Incident> incident(int s, std::size_t id) const {
    return {incident_[s].data() + first_[s][id], first_[s][id + 1] - first_[s][id]};
  }

  Side side_at(std::size_t node, const Point2& w, int other) const;
  bool bounds_properly(std::size_t node, int other) const;
  Side side_of_untouched(int s, std::size_t l) const;

  const Boundary (&loops_)[2];
  detail::PointIndex index_;
  std::vector<std::vector<std::size_t>> ids_[2];
  std::vector<std::uint8_t> occurrences_[2];  // per vertex id: 0, 1, or 2 for more
  std::vector<std::vector<char>> cancelled_[2];
  std::vector<std::size_t> first_[2];
  std::vector<Incident> incident_[2];
};

// Counter-clockwise rank of direction c around v from the ray v -> w: 0 along the ray,
// 1 strictly left of it, 2 straight back, 3 strictly right.
int counter_clockwise_rank(const Point2& v, const Point2& w, const Point2& c) {
  switch (orient2d(v, w, c)) {
    case Orientation::kCounterClockwise:
      return 1;
    case Orientation::kClockwise:
      return 3;
    case Orientation::kCollinear:
      break;
  }
  // Collinear: the dot product's sign is far from its rounding.
  const double dot = (w.x - v.x) * (c.x - v.x) + (w.y - v.y) * (c.y - v.y);
  return dot > 0.0 ? 0 : 2;
}

// The side of the other operand (`other`) that the edge node -> w lies on, from the other
// operand's live edges at the node alone: the plane graph is noded, so the edge meets
// them nowhere else. Turning counter-clockwise from the edge, the first of them met has
// the region on its left: the edge lies inside when that one arrives at the node (its
// region is just clockwise of it), outside when it leaves (its region is beyond it). One
// running along the edge itself is shared with it.
Side Overlay::side_at(std::size_t node, const Point2& w, int other) const {
  const Point2& v = index_.point(node);
  const Incident* first = nullptr;
  int first_rank = 4;
  for (const Incident& e : incident(other, node)) {
    const int rank = counter_clockwise_rank(v, w, e.far);
    if (rank == 0) return e.leaves ? Side::kSharedSame : Side::kSharedOpposite;
    if (first == nullptr || rank < first_rank ||
        (rank == first_rank && rank != 2 &&
         orient2d(v, first->far, e.far) == Orientation::kClockwise)) {
      first = &e;
      first_rank = rank;
    }
  }
  if (!bounds_properly(node, other)) {
    // The other boundary does not pass through here as the boundary of a region does
    // (snapping folded some of it onto itself): no local picture holds, so the edge is
    // located exactly against all of it.
    const Location where = detail::locate_midpoint(v, w, loops_[other]);
    if (where != Location::kBoundary)
      return where == Location::kInside ? Side::kInside : Side::kOutside;
  }
  return first->leaves ? Side::kOutside : Side::kInside;
}

// Whether the other operand's live edges at the node alternate, around it, between
// leaving and arriving, no two along the same ray: how the boundary of a region whose
// winding number is 0 or 1 passes through a point.
bool Overlay::bounds_properly(std::size_t node, int other) const {
  const std::span<const Incident> edges = incident(other, node);
  if (edges.size() == 2) {
    if (edges[0].leaves == edges[1].leaves) return false;
    const Point2& v = index_.point(node);
    return counter_clockwise_rank(v, edges[0].far, edges[1].far) != 0;
  }
  if (edges.size() % 2 != 0) return false;
  const Point2& v = index_.point(node);
  std::vector<Incident> around(edges.begin(), edges.end());
  const Point2 ray = around.front().far;
  std::sort(around.begin() + 1, around.end(), [&](const Incident& a, const Incident& b) {
    const int ra = counter_clockwise_rank(v, ray, a.far),
              rb = counter_clockwise_rank(v, ray, b.far);
    if (ra != rb) return ra < rb;
    return ra != 2 && orient2d(v, a.far, b.far) == Orientation::kCounterClockwise;
  });
  for (std::size_t i = 0; i < around.size(); ++i) {
    const Incident& a = around[i];
    const Incident& b = around[(i + 1) % around.size()];
    if (a.leaves == b.leaves || counter_clockwise_rank(v, a.far, b.far) == 0) return false;
  }
  return true;
}

// A loop of operand s that meets the other operand nowhere lies wholly on one side: the
// side of any of its vertices that the other operand does not have (such a vertex lies
// off its boundary, the graph being noded), else of the middle of an edge.
Side Overlay::side_of_untouched(int s, std::size_t l) const {
  const Boundary& other = loops_[1 - s];
  const Loop2& loop = loops_[s][l];
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (occurrences_[1 - s][ids_[s][l][i]] != 0) continue;
    const Location where = detail::locate(loop[i], other);
    if (where != Location::kBoundary)
      return where == Location::kInside ? Side::kInside : Side::kOutside;
  }
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Location where = detail::locate_midpoint(loop[i], loop[(i + 1) % loop.size()], other);
    if (where != Location::kBoundary)
      return where == Location::kInside ? Side::kInside : Side::kOutside;
  }
  return Side::kOutside;  // on the other boundary throughout: only cancelled edges are left
}

ClassifiedEdges Overlay::classify(int s) const {
  ClassifiedEdges out;
  auto bucket = [&out](Side side) -> std::vector<DirectedEdge>& {
    switch (side) {
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
  const int other = 1 - s;
  for (std::size_t l = 0; l < loops_[s].size(); ++l) {
    const Loop2& loop = loops_[s][l];
    const std::vector<std::size_t>& ids = ids_[s][l];
    const std::vector<char>& cancelled = cancelled_[s][l];
    const std::size_t n = loop.size();
    if (n < 2) continue;
    // A node where the other operand has live edges: a side is decided there.
    auto deciding = [&](std::size_t i) {
      return is_node(ids[i]) && !incident(other, ids[i]).empty();
    };
    std::size_t start = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (deciding(i)) {
        start = i;
        break;
      }
    }
    Side side = start == n ? side_of_untouched(s, l) : Side::kOutside;
    if (start == n) start = 0;
    // Between nodes the edges touch nothing of the other operand: each keeps the side of
    // the edge before it. The side of an edge that is a piece of a shared segment is
    // decided at whichever end is a node.
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = (start + k) % n;
      const std::size_t j = (i + 1) % n;
      if (deciding(i)) {
        side = side_at(ids[i], loop[j], other);
      } else if (deciding(j)) {
        side = side_at(ids[j], loop[i], other);
        // Seen from the far end, a shared edge runs the other way.
        if (side == Side::kSharedSame) {
          side = Side::kSharedOpposite;
        } else if (side == Side::kSharedOpposite) {
          side = Side::kSharedSame;
        }
      } else if (side == Side::kSharedSame || side == Side::kSharedOpposite) {
        // Past a shared edge onto one that meets nothing: never, the graph being noded.
        side = Side::kOutside;
      }
      if (!cancelled[i]) bucket(side).push_back({loop[i], loop[j]});
    }
  }
  return out;
}

}  // namespace

std::array<ClassifiedEdges, 2> classify_edges(const std::vector<Loop2> (&loops)[2]) {
  const Overlay overlay(loops);
  return {overlay.classify(0), overlay.classify(1)};
}

}  // namespace shadowgen::clipper::detail
