#include "plane_lifter.h"

#include <algorithm>

namespace shadowgen::detail {

PlaneLifter::PlaneLifter(const hsr::Plane3& plane, const glm::dvec3& origin)
    : chart_(hsr::chart_facing(plane.normal)), plane_(plane), origin_(origin) {}

clipper::Loop2 PlaneLifter::flatten(const hsr::Loop3& loop) {
  clipper::Loop2 out;
  out.reserve(loop.size());
  for (const glm::dvec3& p : loop) {
    const clipper::Point2 q = chart_(p - origin_);
    known_.emplace(q, p);
    out.push_back(q);
  }
  return out;
}

clipper::PolygonWithHoles2 PlaneLifter::flatten(const hsr::Polygon3& polygon) {
  clipper::PolygonWithHoles2 q{flatten(polygon.outer), {}};
  for (const hsr::Loop3& h : polygon.holes) q.holes.push_back(flatten(h));
  return q;
}

glm::dvec3 PlaneLifter::offset_on_plane(const clipper::Point2& q) const {
  const glm::dvec3& n = plane_.normal;
  switch (chart_.dropped_axis) {
    case 0:  // (y, z) kept
      return {-(n.y * q.x + n.z * q.y) / n.x, q.x, q.y};
    case 1:  // (z, x) kept
      return {q.y, -(n.z * q.x + n.x * q.y) / n.y, q.x};
    default:  // (x, y) kept
      return {q.x, q.y, -(n.x * q.x + n.y * q.y) / n.z};
  }
}

hsr::Loop3 PlaneLifter::lift(const clipper::Loop2& loop) const {
  hsr::Loop3 out;
  out.reserve(loop.size());
  for (const clipper::Point2& q : loop) {
    const auto it = known_.find(q);
    out.push_back(it != known_.end() ? it->second : origin_ + offset_on_plane(q));
  }
  return out;
}

std::vector<hsr::Polygon3> PlaneLifter::lift(const clipper::PolygonSet2& set) const {
  const bool flip = plane_.normal[chart_.dropped_axis] < 0.0;
  std::vector<hsr::Polygon3> out;
  out.reserve(set.size());
  for (const clipper::PolygonWithHoles2& q : set) {
    hsr::Polygon3 p{lift(q.outer), {}};
    for (const clipper::Loop2& h : q.holes) p.holes.push_back(lift(h));
    if (flip) {
      std::reverse(p.outer.begin(), p.outer.end());
      for (hsr::Loop3& h : p.holes) std::reverse(h.begin(), h.end());
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace shadowgen::detail
