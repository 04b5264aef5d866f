#include "tests/support/transform.h"

namespace shadowgen::test {
namespace {

using clipper::Loop2;
using clipper::Point2;
using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

template <typename Map>
PolygonSet2 transformed(const PolygonSet2& polygons, Map map) {
  PolygonSet2 result = polygons;
  for (PolygonWithHoles2& polygon : result) {
    for (Point2& p : polygon.outer) p = map(p);
    for (Loop2& hole : polygon.holes) {
      for (Point2& p : hole) p = map(p);
    }
  }
  return result;
}

}  // namespace

PolygonSet2 translated(const PolygonSet2& polygons, Point2 offset) {
  return transformed(polygons, [offset](Point2 p) {
    return Point2{p.x + offset.x, p.y + offset.y};
  });
}

PolygonSet2 scaled(const PolygonSet2& polygons, double factor) {
  return transformed(polygons, [factor](Point2 p) { return Point2{p.x * factor, p.y * factor}; });
}

}  // namespace shadowgen::test
