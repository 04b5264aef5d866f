#include "crossing.h"

#include <algorithm>
#include <cmath>

#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {

Point2 crossing_point(const Point2& a_start, const Point2& a_end, const Point2& b_start,
                      const Point2& b_end) {
  // Each segment taken from its lexicographically smaller end, so that an edge and its
  // reverse (the same stretch in the inside and in the outside pieces) give the very
  // same point.
  const bool a_forward = a_start < a_end;
  const bool b_forward = b_start < b_end;
  const Point2& a0 = a_forward ? a_start : a_end;
  const Point2& a1 = a_forward ? a_end : a_start;
  const Point2& b0 = b_forward ? b_start : b_end;
  const Point2& b1 = b_forward ? b_end : b_start;
  auto length2 = [](const Point2& p, const Point2& q) {
    const double dx = q.x - p.x, dy = q.y - p.y;
    return dx * dx + dy * dy;
  };
  // The same answer whichever segment comes first: ties in length go to the segment with
  // the smaller first endpoint.
  const double la = length2(a0, a1), lb = length2(b0, b1);
  const bool along_a = la < lb || (la == lb && (a0 < b0 || (a0 == b0 && a1 < b1)));
  const Point2& p0 = along_a ? a0 : b0;
  const Point2& p1 = along_a ? a1 : b1;
  const Point2& q0 = along_a ? b0 : a0;
  const Point2& q1 = along_a ? b1 : a1;
  const double o0 = std::fabs(orient2d_value(q0, q1, p0));
  const double o1 = std::fabs(orient2d_value(q0, q1, p1));
  const double t = o0 / (o0 + o1);
  Point2 p{p0.x + t * (p1.x - p0.x), p0.y + t * (p1.y - p0.y)};
  // The parameter is within 6u of its own value (each determinant 2u, whose errors half
  // cancel in the quotient, then the sum and the quotient u each), and the step along the
  // shorter segment, t·(p1 − p0), within 8u of its own value per coordinate with the
  // difference and the product: that coordinate of the point is off by at most
  // 8u·|P.x − p0.x| + u·|P.x| (the sum's rounding). That is within 5u·|P.x| where the step
  // is at most 3/8 of the coordinate (4u with room for p standing for P), in each
  // coordinate; or where the whole shorter segment is short beside the smaller coordinate
  // (4·length + |P.x| + |P.y| ≤ 4·min(|P.x|, |P.y|)), which holds for crossings of short
  // edges away from the axes. Elsewhere (long edges, crossings near an axis), exactly.
  const double smaller = std::min(std::fabs(p.x), std::fabs(p.y));
  const double bound = 4.0 * std::sqrt(std::min(la, lb)) + std::fabs(p.x) + std::fabs(p.y);
  const bool short_steps = 8.0 * std::fabs(p.x - p0.x) <= 3.0 * std::fabs(p.x) &&
                           8.0 * std::fabs(p.y - p0.y) <= 3.0 * std::fabs(p.y);
  if (!short_steps && !(bound <= 4.0 * smaller)) p = crossing_point_exact(p0, p1, q0, q1);
  const double xlo = std::max(std::min(a0.x, a1.x), std::min(b0.x, b1.x));
  const double xhi = std::min(std::max(a0.x, a1.x), std::max(b0.x, b1.x));
  const double ylo = std::max(std::min(a0.y, a1.y), std::min(b0.y, b1.y));
  const double yhi = std::min(std::max(a0.y, a1.y), std::max(b0.y, b1.y));
  p.x = std::clamp(p.x, xlo, xhi);
  p.y = std::clamp(p.y, ylo, yhi);
  return p;
}

}  // namespace shadowgen::clipper::detail
