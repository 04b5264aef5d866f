#include "hsr/triangles_meet.h"

#include <cstddef>

#include "clipper/predicates.h"
#include "hsr/plane_chart.h"

namespace shadowgen::hsr {
namespace {

using clipper::Orientation;
using clipper::Point2;

int sign(Orientation o) { return static_cast<int>(o); }

int orient3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  return sign(clipper::orient3d(a, b, c, d));
}

// Drops coordinate `axis` (the plane chart's map): exact, and one-to-one on a plane not
// parallel to that axis.
Point2 drop(const glm::dvec3& p, int axis) { return PlaneChart{axis}(p); }

// An axis along which the triangle (not degenerate) projects to a triangle: then the
// projection of its plane is one-to-one, and coplanar questions are settled in 2D.
int projecting_axis(const Triangle3& t) {
  for (const int axis : {2, 0, 1}) {
    if (clipper::orient2d(drop(t[0], axis), drop(t[1], axis), drop(t[2], axis)) !=
        Orientation::kCollinear) {
      return axis;
    }
  }
  return 2;  // degenerate: not asked
}

// Whether the closed 2D segments a-b and c-d share a point.
bool segments_meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = sign(clipper::orient2d(a, b, c)), o2 = sign(clipper::orient2d(a, b, d));
  const int o3 = sign(clipper::orient2d(c, d, a)), o4 = sign(clipper::orient2d(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && clipper::on_segment(a, b, c)) || (o2 == 0 && clipper::on_segment(a, b, d)) ||
         (o3 == 0 && clipper::on_segment(c, d, a)) || (o4 == 0 && clipper::on_segment(c, d, b));
}

// Whether p lies in the closed 2D triangle t0, t1, t2 (not degenerate).
bool in_triangle(const Point2& p, const Point2& t0, const Point2& t1, const Point2& t2) {
  const int turn = sign(clipper::orient2d(t0, t1, t2));
  return sign(clipper::orient2d(t0, t1, p)) * turn >= 0 &&
         sign(clipper::orient2d(t1, t2, p)) * turn >= 0 &&
         sign(clipper::orient2d(t2, t0, p)) * turn >= 0;
}

// Whether the segment p-q and the triangle t, all in one plane, share a point: an end
// inside, or the segment across a side (in the plane's projection along `axis`).
bool segment_meets_triangle_in_plane(const glm::dvec3& p, const glm::dvec3& q, const Triangle3& t,
                                     int axis) {
  const Point2 P = drop(p, axis), Q = drop(q, axis);
  const Point2 T0 = drop(t[0], axis), T1 = drop(t[1], axis), T2 = drop(t[2], axis);
  return in_triangle(P, T0, T1, T2) || in_triangle(Q, T0, T1, T2) || segments_meet(P, Q, T0, T1) ||
         segments_meet(P, Q, T1, T2) || segments_meet(P, Q, T2, T0);
}

// Whether segment u-x, u a corner of t and x in t's plane, enters t from u: x lies in
// the closed angle of t at u (a direction within it, not against it).
bool enters_from_corner(const glm::dvec3& u, const glm::dvec3& x, const Triangle3& t,
                        bool in_plane) {
  if (!in_plane && orient3(t[0], t[1], t[2], x) != 0) return false;  // it leaves the plane at u
  const int axis = projecting_axis(t);
  std::size_t k = 0;
  while (t[k] != u) ++k;
  const Point2 U = drop(u, axis), X = drop(x, axis);
  const Point2 C1 = drop(t[(k + 1) % 3], axis), C2 = drop(t[(k + 2) % 3], axis);
  const int turn = sign(clipper::orient2d(U, C1, C2));
  return sign(clipper::orient2d(U, C1, X)) * turn >= 0 &&
         sign(clipper::orient2d(U, X, C2)) * turn >= 0;
}

}  // namespace

bool degenerate(const Triangle3& t) {
  for (const int axis : {0, 1, 2}) {
    if (clipper::orient2d(drop(t[0], axis), drop(t[1], axis), drop(t[2], axis)) !=
        Orientation::kCollinear) {
      return false;
    }
  }
  return true;
}

bool segment_meets_triangle(const glm::dvec3& p, const glm::dvec3& q, const Triangle3& t) {
  const int s1 = orient3(t[0], t[1], t[2], p), s2 = orient3(t[0], t[1], t[2], q);
  if (s1 * s2 > 0) return false;  // both strictly on one side of the plane
  if (s1 == 0 && s2 == 0) return segment_meets_triangle_in_plane(p, q, t, projecting_axis(t));
  // The segment reaches the plane at one point; its line passes through the closed
  // triangle when it passes no side of it the other way round from another (the signs of
  // the lines' Plücker products, here orient3d of the line with each side).
  const int o1 = orient3(p, q, t[0], t[1]), o2 = orient3(p, q, t[1], t[2]);
  const int o3 = orient3(p, q, t[2], t[0]);
  return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

bool triangles_meet(const Triangle3& a, const Triangle3& b) {
  // Corners all strictly on one side of the other's plane: apart.
  auto one_side = [](const Triangle3& plane, const Triangle3& t) {
    const int s0 = orient3(plane[0], plane[1], plane[2], t[0]);
    return s0 != 0 && s0 == orient3(plane[0], plane[1], plane[2], t[1]) &&
           s0 == orient3(plane[0], plane[1], plane[2], t[2]);
  };
  if (one_side(a, b) || one_side(b, a)) return false;
  // Two closed triangles that meet have a point of their common part on a side of one of
  // them: the ends of the segment where their planes' line runs through both, or, when
  // coplanar, a side of one crossing the other or the whole of one inside the other.
  for (std::size_t k = 0; k < 3; ++k) {
    if (segment_meets_triangle(a[k], a[(k + 1) % 3], b)) return true;
    if (segment_meets_triangle(b[k], b[(k + 1) % 3], a)) return true;
  }
  return false;
}

bool triangles_overlap_beyond_shared(const Triangle3& a, const Triangle3& b, bool coplanar) {
  std::size_t shared = 0, ia[3] = {}, ib[3] = {};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      if (a[i] == b[j]) {
        ia[shared] = i;
        ib[shared] = j;
        ++shared;
      }
    }
  }
  if (shared >= 3) return true;
  const int axis = coplanar ? projecting_axis(a) : 2;
  // A side of one meeting the other, decided in the plane where they share it.
  auto meets = [&](const glm::dvec3& p, const glm::dvec3& q, const Triangle3& t) {
    return coplanar ? segment_meets_triangle_in_plane(p, q, t, axis)
                    : segment_meets_triangle(p, q, t);
  };
  if (shared == 0) {
    if (!coplanar) return triangles_meet(a, b);
    for (std::size_t k = 0; k < 3; ++k) {
      if (meets(a[k], a[(k + 1) % 3], b) || meets(b[k], b[(k + 1) % 3], a)) return true;
    }
    return false;
  }
  if (shared == 2) {
    // Their planes meet along the common edge, and each triangle meets that line in the
    // edge alone: unless they are coplanar, that is all they share.
    const glm::dvec3& u = a[ia[0]];
    const glm::dvec3& v = a[ia[1]];
    const glm::dvec3& x = a[3 - ia[0] - ia[1]];
    const glm::dvec3& y = b[3 - ib[0] - ib[1]];
    if (!coplanar && orient3(u, v, x, y) != 0) return false;
    const int in = coplanar ? axis : projecting_axis(a);
    const int sx = sign(clipper::orient2d(drop(u, in), drop(v, in), drop(x, in)));
    const int sy = sign(clipper::orient2d(drop(u, in), drop(v, in), drop(y, in)));
    return sx * sy >= 0;
  }
  // One common corner u. Were their common part more than u, it would hold a segment from
  // u whose far end lies on a side of one of them: on the side facing u (across from
  // it), or along a side from u, which then lies in the other's plane and enters it.
  const glm::dvec3& u = a[ia[0]];
  const glm::dvec3& a1 = a[(ia[0] + 1) % 3];
  const glm::dvec3& a2 = a[(ia[0] + 2) % 3];
  const glm::dvec3& b1 = b[(ib[0] + 1) % 3];
  const glm::dvec3& b2 = b[(ib[0] + 2) % 3];
  if (!coplanar) {
    // The other corners of one strictly on one side of the other's plane: it meets that
    // plane at u alone.
    const int s1 = orient3(a[0], a[1], a[2], b1), s2 = orient3(a[0], a[1], a[2], b2);
    if (s1 * s2 > 0) return false;
    const int r1 = orient3(b[0], b[1], b[2], a1), r2 = orient3(b[0], b[1], b[2], a2);
    if (r1 * r2 > 0) return false;
  }
  return meets(a1, a2, b) || meets(b1, b2, a) || enters_from_corner(u, a1, b, coplanar) ||
         enters_from_corner(u, a2, b, coplanar) || enters_from_corner(u, b1, a, coplanar) ||
         enters_from_corner(u, b2, a, coplanar);
}

}  // namespace shadowgen::hsr
