#include "point_location.h"

#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {
namespace {

int compare_x(const Point2& p, double x) { return p.x < x ? -1 : (p.x > x ? 1 : 0); }
int compare_y(const Point2& p, double y) { return p.y < y ? -1 : (p.y > y ? 1 : 0); }

// Adds loop's contribution to the winding number of p; returns false when p lies on it.
// P is a Point2 or a Midpoint2: every decision goes through compare_x, compare_y and
// orient2d, which are exact for both.
template <typename P>
bool accumulate_winding(const P& p, const Loop2& loop, int& winding) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[i + 1 == n ? 0 : i + 1];
    const int ay = compare_y(p, a.y);  // sign of p.y − a.y
    const int by = compare_y(p, b.y);
    if (ay >= 0) {   // a.y <= p.y
      if (by < 0) {  // b.y > p.y
        const Orientation o = orient2d(a, b, p);
        if (o == Orientation::kCollinear) return false;
        if (o == Orientation::kCounterClockwise) ++winding;
      } else if (ay == 0 && by == 0) {
        // A horizontal edge at p's height: p is on it when it lies between the ends.
        const int ax = compare_x(p, a.x), bx = compare_x(p, b.x);
        if (ax * bx <= 0) return false;
      } else if (by == 0 && compare_x(p, b.x) == 0) {
        return false;
      }
    } else if (by >= 0) {  // a.y > p.y >= b.y
      const Orientation o = orient2d(a, b, p);
      if (o == Orientation::kCollinear) return false;
      if (o == Orientation::kClockwise) --winding;
    }
  }
  return true;
}

template <typename P>
Location locate_in_loop(const P& p, const Loop2& loop) {
  int winding = 0;
  if (!accumulate_winding(p, loop, winding)) return Location::kBoundary;
  return winding != 0 ? Location::kInside : Location::kOutside;
}

template <typename P>
Location locate_in_loops(const P& p, const std::vector<Loop2>& loops) {
  int winding = 0;
  for (const Loop2& loop : loops) {
    if (!accumulate_winding(p, loop, winding)) return Location::kBoundary;
  }
  return winding > 0 ? Location::kInside : Location::kOutside;
}

}  // namespace

Location locate(const Point2& p, const Loop2& loop) { return locate_in_loop(p, loop); }

Location locate(const Point2& p, const std::vector<Loop2>& loops) {
  return locate_in_loops(p, loops);
}

Location locate_midpoint(const Point2& a, const Point2& b, const Loop2& loop) {
  return locate_in_loop(Midpoint2{a, b}, loop);
}

Location locate_midpoint(const Point2& a, const Point2& b, const std::vector<Loop2>& loops) {
  return locate_in_loops(Midpoint2{a, b}, loops);
}

bool add_winding_number(const Point2& p, const Loop2& loop, int& winding) {
  return accumulate_winding(p, loop, winding);
}

bool add_winding_number(const Midpoint2& p, const Loop2& loop, int& winding) {
  return accumulate_winding(p, loop, winding);
}

}  // namespace shadowgen::clipper::detail
