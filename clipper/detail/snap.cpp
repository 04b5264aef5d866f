#include "clipper/detail/snap.h"

#include <algorithm>
#include <cmath>

#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {

double snap_distance(const Point2& e0, const Point2& e1) {
  constexpr double kUnit = 0x1p-53;
  const double length = std::hypot(e1.x - e0.x, e1.y - e0.y);
  const double magnitude =
      std::max({std::fabs(e0.x), std::fabs(e0.y), std::fabs(e1.x), std::fabs(e1.y)});
  return 2.0 * (4.0 * kUnit * length + kUnit * magnitude);
}

bool within_snap_distance(const Point2& v, const Point2& e0, const Point2& e1) {
  if (v == e0 || v == e1) return false;
  const double dx = e1.x - e0.x, dy = e1.y - e0.y;
  const double length2 = dx * dx + dy * dy;
  const double t = ((v.x - e0.x) * dx + (v.y - e0.y) * dy) / length2;
  if (!(t > 0.0 && t < 1.0)) return false;
  if (orient2d(e0, e1, v) == Orientation::kCollinear) return true;
  // |cross| / |edge| is the distance; the cross product's own rounding is far below it.
  return std::fabs(orient2d_value(e0, e1, v)) <= snap_distance(e0, e1) * std::sqrt(length2);
}

}  // namespace shadowgen::clipper::detail
