#pragma once

// A loop put together from its edges' routes, as the snapping returns it (snap_rounding.h):
// repeats in a row dropped, the last point dropped while it is the first again, and
// nothing left of a loop snapped to a single point (it bounds nothing).

#include <cstddef>
#include <utility>

#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

class LoopOfRoutes {
 public:
  explicit LoopOfRoutes(std::size_t expected) { out_.reserve(expected); }
  void add(const Point2& p) {
    if (out_.empty() || out_.back() != p) out_.push_back(p);
  }
  Loop2 take() {
    while (out_.size() > 1 && out_.back() == out_.front()) out_.pop_back();
    if (out_.size() < 2) out_.clear();
    return std::move(out_);
  }

 private:
  Loop2 out_;
};

}  // namespace shadowgen::clipper::detail
