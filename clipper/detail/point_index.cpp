#include "point_index.h"

namespace shadowgen::clipper::detail {

PointIndex::PointIndex(std::size_t expected) { reset(expected); }

void PointIndex::reset(std::size_t expected) {
  std::size_t capacity = 16;
  while (capacity < 2 * expected) capacity *= 2;  // load factor at most 1/2
  slots_.assign(capacity, 0);
  mask_ = capacity - 1;
  points_.clear();
  points_.reserve(expected);
}

std::size_t PointIndex::id(const Point2& p) {
  for (std::size_t slot = Point2Hash{}(p)&mask_;; slot = (slot + 1) & mask_) {
    const std::size_t entry = slots_[slot];
    if (entry == 0) {
      if (2 * (points_.size() + 1) > slots_.size()) {
        grow();
        return id(p);
      }
      points_.push_back(p);
      slots_[slot] = points_.size();
      return points_.size() - 1;
    }
    if (points_[entry - 1] == p) return entry - 1;
  }
}

void PointIndex::grow() {
  slots_.assign(2 * slots_.size(), 0);
  mask_ = slots_.size() - 1;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    std::size_t slot = Point2Hash{}(points_[i]) & mask_;
    while (slots_[slot] != 0) slot = (slot + 1) & mask_;
    slots_[slot] = i + 1;
  }
}

}  // namespace shadowgen::clipper::detail
