#include "clipper/detail/point_location.h"

#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {
namespace {

// Adds loop's contribution to the winding number of p; returns false when p lies on it.
bool accumulate_winding(const Point2& p, const Loop2& loop, int& winding) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[i + 1 == n ? 0 : i + 1];
    if (a.y <= p.y) {
      if (b.y > p.y) {
        const Orientation o = orient2d(a, b, p);
        if (o == Orientation::kCollinear) return false;
        if (o == Orientation::kCounterClockwise) ++winding;
      } else if (b.y == p.y && a.y == p.y && on_segment(a, b, p)) {
        return false;  // horizontal edge through p
      } else if (b.y == p.y && b.x == p.x) {
        return false;
      }
    } else if (b.y <= p.y) {
      const Orientation o = orient2d(a, b, p);
      if (o == Orientation::kCollinear) return false;
      if (o == Orientation::kClockwise) --winding;
    }
  }
  return true;
}

}  // namespace

Location locate(const Point2& p, const Loop2& loop) {
  int winding = 0;
  if (!accumulate_winding(p, loop, winding)) return Location::kBoundary;
  return winding != 0 ? Location::kInside : Location::kOutside;
}

Location locate(const Point2& p, const std::vector<Loop2>& loops) {
  int winding = 0;
  for (const Loop2& loop : loops) {
    if (!accumulate_winding(p, loop, winding)) return Location::kBoundary;
  }
  return winding > 0 ? Location::kInside : Location::kOutside;
}

}  // namespace shadowgen::clipper::detail
