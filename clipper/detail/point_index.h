#pragma once

// Dense ids for the distinct points of a boundary: 0, 1, 2, ... in order of first sight.
// An open-addressing table on the points' exact bit patterns (Point2Hash), in two flat
// arrays: the tracer names every endpoint of every traced edge, and a node-based hash map
// spent more time allocating than hashing.

#include <cstddef>
#include <vector>

#include "clipper/point.h"

namespace shadowgen::clipper::detail {

class PointIndex {
 public:
  // Room for `expected` distinct points without growing.
  explicit PointIndex(std::size_t expected);

  // Empty again, with room for `expected` points, in the storage it has where that is
  // enough (an index reused clip after clip allocates nothing).
  void reset(std::size_t expected);

  // The id of p, a new one (the current size) if p was not seen before.
  std::size_t id(const Point2& p);
  std::size_t size() const { return points_.size(); }
  const Point2& point(std::size_t id) const { return points_[id]; }

 private:
  void grow();

  std::vector<std::size_t> slots_;  // id + 1, or 0 for an empty slot
  std::vector<Point2> points_;      // by id
  std::size_t mask_ = 0;
};

}  // namespace shadowgen::clipper::detail
