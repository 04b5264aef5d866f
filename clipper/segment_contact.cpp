#include "clipper/segment_contact.h"

#include <algorithm>

#include "clipper/predicates.h"

namespace shadowgen::clipper {

namespace {

using clipper::Point2;

int orientation(const Point2& a, const Point2& b, const Point2& c) {
  return static_cast<int>(clipper::orient2d(a, b, c));
}

bool within_box(const Point2& a, const Point2& b, const Point2& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

}  // namespace

SegmentContact segment_contact(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  if (o1 * o2 > 0) return {};
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o3 * o4 > 0) return {};
  if (o1 == 0 && o2 == 0) {
    // Collinear: along a line, the lexicographic order of points is their order on it.
    const Point2 lo = std::max(std::min(a, b), std::min(c, d));
    const Point2 hi = std::min(std::max(a, b), std::max(c, d));
    if (hi < lo) return {};
    if (hi == lo) return {Contact::kTouch, lo};
    return {Contact::kOverlap, {}};
  }
  if (o1 * o2 < 0 && o3 * o4 < 0) return {Contact::kCross, {}};
  // Not collinear, so at most one common point: an endpoint lying on the other segment.
  if (o1 == 0 && within_box(a, b, c)) return {Contact::kTouch, c};
  if (o2 == 0 && within_box(a, b, d)) return {Contact::kTouch, d};
  if (o3 == 0 && within_box(c, d, a)) return {Contact::kTouch, a};
  if (o4 == 0 && within_box(c, d, b)) return {Contact::kTouch, b};
  return {};
}

}  // namespace shadowgen::clipper
