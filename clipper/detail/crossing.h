#pragma once

// The rounded crossing point of two properly crossing segments: the one construction of
// the clipper (clip.h states its error bound).

#include <cmath>

#include "clipper/point.h"

namespace shadowgen::clipper::detail {

// Segments a0-a1 and b0-b1 must cross properly (each strictly separates the other's
// endpoints). Each coordinate of the result lies within 5u of its own magnitude,
//     |x − P.x| ≤ 5u·|P.x|,  |y − P.y| ≤ 5u·|P.y|,   u = 2^-53,
// of the exact crossing P, whatever the angle and however long the segments. Where the
// step along the shorter segment to the point is small beside each coordinate (or that
// segment is short beside the smaller coordinate) this comes from the parameter along it,
// |o0| / (|o0| + |o1|) from two exact orientation determinants of opposite sign rounded
// once each, accurate to a few ulps (error 8u·|P − p0| + u·|P| per coordinate);
// elsewhere (long edges, crossings near an axis) from exact determinants throughout
// (predicates.h). The result is kept inside both segments' boxes and does not depend on
// the order of the two segments or of their endpoints (an edge and its reverse give the
// same point).
Point2 crossing_point(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1);

// The order of points along the segment p -> q, for points on it or a hair off it
// (rounded crossings, vertices it is routed through): by their projections onto its
// direction, where the sign of the difference is certain in doubles; otherwise by the
// coordinate that varies most along the segment, ties by the other one, each in the
// segment's own direction. Exact for points on the segment. Projections order points
// off it the same way along any segment close to parallel, run either way: two edges of
// a needle routed through the same points a hair apart then pass them in opposite
// orders and cancel, where ordering each by its main coordinate (x for one, y for the
// other, at 45°) crossed them. The tie-break matters: two crossings less than an ulp
// apart in the main coordinate (a line passing within rounding of a vertex crosses both
// of its edges) still differ in the other one, and taken the wrong way round they fold
// the boundary.
class AlongSegment {
 public:
  AlongSegment(const Point2& p, const Point2& q)
      : dx_(q.x - p.x),
        dy_(q.y - p.y),
        by_x_(std::fabs(dx_) >= std::fabs(dy_)),
        main_ascending_(by_x_ ? q.x > p.x : q.y > p.y),
        other_ascending_(by_x_ ? q.y > p.y : q.x > p.x) {}

  bool operator()(const Point2& a, const Point2& b) const {
    // (b − a)·d, each difference within u of its own value and the sum of two products
    // within 3u of the sum of their magnitudes: the 4u bound covers both.
    const double px = (b.x - a.x) * dx_, py = (b.y - a.y) * dy_;
    const double dot = px + py;
    if (std::fabs(dot) > 0x1p-51 * (std::fabs(px) + std::fabs(py))) return dot > 0.0;
    const double ua = by_x_ ? a.x : a.y, ub = by_x_ ? b.x : b.y;
    if (ua != ub) return main_ascending_ ? ua < ub : ua > ub;
    const double va = by_x_ ? a.y : a.x, vb = by_x_ ? b.y : b.x;
    return other_ascending_ ? va < vb : va > vb;
  }

 private:
  double dx_, dy_;
  bool by_x_, main_ascending_, other_ascending_;
};

}  // namespace shadowgen::clipper::detail
