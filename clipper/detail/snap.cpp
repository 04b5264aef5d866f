#include "clipper/detail/snap.h"

#include <algorithm>
#include <cmath>

#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {

double snap_distance(const Point2& e0, const Point2& e1) {
  constexpr double kUnit = 0x1p-53;
  // Not hypot: coordinates are below 1e150 (predicates.h), so the squares cannot
  // overflow, and sqrt is several times cheaper on this hot path.
  const double dx = e1.x - e0.x, dy = e1.y - e0.y;
  const double length = std::sqrt(dx * dx + dy * dy);
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
  // |cross| / |edge| is the distance. The cross product in doubles is within
  // 4u·permanent of the exact one (orient2d's filter); only where that leaves the
  // comparison with the threshold open is it evaluated exactly.
  const double threshold = snap_distance(e0, e1) * std::sqrt(length2);
  const double left = dx * (v.y - e0.y), right = dy * (v.x - e0.x);
  const double cross = std::fabs(left - right);
  const double error = 0x1p-51 * (std::fabs(left) + std::fabs(right));
  if (cross - error > threshold) return false;
  if (orient2d(e0, e1, v) == Orientation::kCollinear) return true;
  if (cross + error <= threshold) return true;
  return std::fabs(orient2d_value(e0, e1, v)) <= threshold;
}

}  // namespace shadowgen::clipper::detail
