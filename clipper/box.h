#pragma once

#include <algorithm>
#include <cmath>

#include "clipper/polygon.h"

namespace shadowgen::clipper {

// An axis-aligned image-space bounding box.
struct Box2 {
  double xmin = INFINITY, ymin = INFINITY, xmax = -INFINITY, ymax = -INFINITY;

  void add(const clipper::Point2& p) {
    xmin = std::min(xmin, p.x);
    ymin = std::min(ymin, p.y);
    xmax = std::max(xmax, p.x);
    ymax = std::max(ymax, p.y);
  }
  void add(const Box2& b) {
    xmin = std::min(xmin, b.xmin);
    ymin = std::min(ymin, b.ymin);
    xmax = std::max(xmax, b.xmax);
    ymax = std::max(ymax, b.ymax);
  }
  bool empty() const { return !(xmin <= xmax && ymin <= ymax); }
  // Open overlap: boxes that only touch cannot hold overlapping polygons.
  bool overlaps(const Box2& b) const {
    return xmin < b.xmax && b.xmin < xmax && ymin < b.ymax && b.ymin < ymax;
  }
  // Closed overlap: also boxes that share only a side or a corner. Polygons in such boxes
  // may touch there without overlapping; clip() still takes them through the snap
  // rounding and overlay, so the pieces it returns carry the other operand's vertices
  // where the two touch, as they do where operands overlap.
  bool touches_or_overlaps(const Box2& b) const {
    return xmin <= b.xmax && b.xmin <= xmax && ymin <= b.ymax && b.ymin <= ymax;
  }
  // Closed containment: a loop winds around no point outside its box, and a loop inside
  // another has its box inside the other's.
  bool contains(const clipper::Point2& p) const {
    return xmin <= p.x && p.x <= xmax && ymin <= p.y && p.y <= ymax;
  }
  bool contains(const Box2& b) const {
    return xmin <= b.xmin && b.xmax <= xmax && ymin <= b.ymin && b.ymax <= ymax;
  }
};

inline Box2 box_of(const clipper::Loop2& loop) {
  Box2 b;
  for (const clipper::Point2& q : loop) b.add(q);
  return b;
}

inline Box2 box_of(const clipper::PolygonWithHoles2& p) { return box_of(p.outer); }

inline Box2 box_of(const clipper::Point2& a, const clipper::Point2& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

}  // namespace shadowgen::clipper
