#include "clipper/detail/crossing.h"

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
  const double xlo = std::max(std::min(a0.x, a1.x), std::min(b0.x, b1.x));
  const double xhi = std::min(std::max(a0.x, a1.x), std::max(b0.x, b1.x));
  const double ylo = std::max(std::min(a0.y, a1.y), std::min(b0.y, b1.y));
  const double yhi = std::min(std::max(a0.y, a1.y), std::max(b0.y, b1.y));
  p.x = std::clamp(p.x, xlo, xhi);
  p.y = std::clamp(p.y, ylo, yhi);
  return p;
}

ExactlyAlongSegment::ExactlyAlongSegment(const Point2& e0, const Point2& e1)
    : e0_(e0), e1_(e1), along_(e0, e1), by_x_(std::fabs(e1.x - e0.x) >= std::fabs(e1.y - e0.y)) {}

double ExactlyAlongSegment::rounding(const EdgePoint& p) const {
  if (!p.crossing) return 0.0;
  constexpr double u = 0x1p-53;
  const double length = std::fabs(e1_.x - e0_.x) + std::fabs(e1_.y - e0_.y);
  const double magnitude = std::fabs(p.point.x) + std::fabs(p.point.y);
  return 4.0 * u * length + u * magnitude;  // 1-norms: above the Euclidean bound
}

// -1 when a's exact point comes first, 1 when b's does, 0 when they are the same point.
int ExactlyAlongSegment::exact_order(const EdgePoint& a, const EdgePoint& b) const {
  if (b.crossing) {
    // a comes first when its exact point lies strictly on e0's side of b's segment.
    const Orientation start = orient2d(b.f0, b.f1, e0_);
    const Orientation side = a.crossing ? orient2d_crossing(b.f0, b.f1, e0_, e1_, a.f0, a.f1)
                                        : orient2d(b.f0, b.f1, a.point);
    if (side == Orientation::kCollinear) return 0;
    return side == start ? -1 : 1;
  }
  if (a.crossing) return -exact_order(b, a);
  if (a.point == b.point) return 0;
  return along_(a.point, b.point) ? -1 : 1;  // both exactly on the segment
}

bool ExactlyAlongSegment::operator()(const EdgePoint& a, const EdgePoint& b) const {
  const double ua = by_x_ ? a.point.x : a.point.y;
  const double ub = by_x_ ? b.point.x : b.point.y;
  if (std::fabs(ua - ub) > rounding(a) + rounding(b)) return along_(a.point, b.point);
  const int order = exact_order(a, b);
  if (order != 0) return order < 0;
  return along_(a.point, b.point);
}

}  // namespace shadowgen::clipper::detail
