#include "snap.h"

#include <algorithm>
#include <cmath>

#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {
namespace {

constexpr double kHalfWidth = 12.0 * 0x1p-53;

bool in_pixel(const Point2& p, const Pixel& box) {
  return p.x >= box.xmin && p.x <= box.xmax && p.y >= box.ymin && p.y <= box.ymax;
}

}  // namespace

Pixel hot_pixel(const Point2& p) {
  const double h = snap_distance(p);
  return {p.x - h, p.x + h, p.y - h, p.y + h};
}

double snap_distance(const Point2& p) {
  return kHalfWidth * std::max(std::fabs(p.x), std::fabs(p.y));
}

bool within_snap_distance(const Point2& p, const Point2& q) {
  if (p == q) return false;
  return in_pixel(q, hot_pixel(p)) || in_pixel(p, hot_pixel(q));
}

bool projects_inside(const Point2& v, const Point2& e0, const Point2& e1) {
  if (v == e0 || v == e1) return false;
  const double dx = e1.x - e0.x, dy = e1.y - e0.y;
  const double from_start = (v.x - e0.x) * dx + (v.y - e0.y) * dy;
  const double from_end = (e1.x - v.x) * dx + (e1.y - v.y) * dy;
  return from_start > 0.0 && from_end > 0.0;
}

bool within_snap_distance(const Point2& v, const Point2& e0, const Point2& e1) {
  if (!projects_inside(v, e0, e1)) return false;
  const Pixel box = hot_pixel(v);
  if (std::max(e0.x, e1.x) < box.xmin || std::min(e0.x, e1.x) > box.xmax ||
      std::max(e0.y, e1.y) < box.ymin || std::min(e0.y, e1.y) > box.ymax) {
    return false;
  }
  // The edge's line misses the box when all four corners lie strictly on one side. In
  // doubles first: the corners' determinants far from zero are decided by the filter.
  const Orientation o = orient2d(e0, e1, v);
  if (o == Orientation::kCollinear) return true;
  for (const Point2& corner : {Point2{box.xmin, box.ymin}, Point2{box.xmax, box.ymin},
                               Point2{box.xmin, box.ymax}, Point2{box.xmax, box.ymax}}) {
    if (orient2d(e0, e1, corner) != o) return true;
  }
  return false;
}

}  // namespace shadowgen::clipper::detail
