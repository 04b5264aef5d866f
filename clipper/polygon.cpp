#include "clipper/polygon.h"

#include <algorithm>
#include <cmath>

namespace shadowgen::clipper {

double signed_area(const Loop2& loop) {
  const std::size_t n = loop.size();
  if (n < 3) return 0.0;
  // Relative to the first vertex: far from the origin the products stay small, so the
  // sum does not cancel catastrophically.
  const Point2 o = loop[0];
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double ax = loop[i].x - o.x, ay = loop[i].y - o.y;
    const double bx = loop[i + 1].x - o.x, by = loop[i + 1].y - o.y;
    twice += ax * by - ay * bx;
  }
  return 0.5 * twice;
}

double area(const PolygonWithHoles2& polygon) {
  double a = std::fabs(signed_area(polygon.outer));
  for (const Loop2& hole : polygon.holes) a -= std::fabs(signed_area(hole));
  return a;
}

double area(const PolygonSet2& polygons) {
  double a = 0.0;
  for (const PolygonWithHoles2& p : polygons) a += area(p);
  return a;
}

std::size_t vertex_count(const PolygonWithHoles2& polygon) {
  std::size_t n = polygon.outer.size();
  for (const Loop2& hole : polygon.holes) n += hole.size();
  return n;
}

std::size_t vertex_count(const PolygonSet2& polygons) {
  std::size_t n = 0;
  for (const PolygonWithHoles2& p : polygons) n += vertex_count(p);
  return n;
}

double rounding_area_bound(const Loop2& loop) {
  constexpr double kUnit = 0x1p-53;
  double perimeter = 0.0, magnitude = 0.0;
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[i + 1 == n ? 0 : i + 1];
    perimeter += std::hypot(b.x - a.x, b.y - a.y);
    magnitude = std::max({magnitude, std::fabs(a.x), std::fabs(a.y)});
  }
  return 18.0 * kUnit * (magnitude + 4.0 * perimeter) * perimeter;
}

}  // namespace shadowgen::clipper
