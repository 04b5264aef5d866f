#pragma once

// Loops as rings of linked nodes, what triangulate() works on: hole_bridge.h joins the
// holes into the outer loop's ring, triangulate.cpp cuts ears from it. Nodes are only
// relinked, never moved or erased, so a node's number stays valid throughout.

#include <cstddef>
#include <limits>
#include <vector>

#include "clipper/point.h"
#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {

inline constexpr std::size_t kNoNode = std::numeric_limits<std::size_t>::max();

// orient2d as a number: 1 counter-clockwise, 0 collinear, -1 clockwise.
inline int orientation(const Point2& a, const Point2& b, const Point2& c) {
  return static_cast<int>(orient2d(a, b, c));
}

// A vertex as the triangulation sees it: its point and its number in the caller's loops.
struct Vertex {
  Point2 p;
  std::size_t index;
};
using Ring = std::vector<Vertex>;

struct Node {
  Point2 p;
  std::size_t index;  // the vertex's number in the caller's loops
  std::size_t prev = kNoNode;
  std::size_t next = kNoNode;
};

class NodeRings {
 public:
  // Links the vertices of `ring` into a new ring; returns its first node.
  std::size_t make_ring(const Ring& ring) {
    const std::size_t base = nodes_.size();
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      nodes_.push_back({ring[i].p, ring[i].index, base + (i + n - 1) % n, base + (i + 1) % n});
    }
    return base;
  }

  std::size_t size() const { return nodes_.size(); }
  const Point2& at(std::size_t n) const { return nodes_[n].p; }
  const Point2& prev_at(std::size_t n) const { return nodes_[nodes_[n].prev].p; }
  const Point2& next_at(std::size_t n) const { return nodes_[nodes_[n].next].p; }

  // Direction n -> w points strictly into the polygon's interior at node n (the interior
  // lies left of the ring).
  bool locally_inside(std::size_t n, const Point2& w) const {
    const Point2& a = prev_at(n);
    const Point2& b = at(n);
    const Point2& c = next_at(n);
    const bool left_of_in = orientation(a, b, w) > 0;
    const bool left_of_out = orientation(b, c, w) > 0;
    if (orientation(a, b, c) > 0) return left_of_in && left_of_out;
    return left_of_in || left_of_out;
  }

 protected:
  std::vector<Node> nodes_;
};

}  // namespace shadowgen::clipper::detail
