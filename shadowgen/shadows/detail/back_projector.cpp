#include "back_projector.h"

namespace shadowgen::detail {

BackProjector::BackProjector(const hsr::View& view, const hsr::Polygon3& polygon,
                             const hsr::Plane3& plane)
    : view_(view), normal_(plane.normal) {
  auto add = [this](const hsr::Loop3& loop) {
    for (const glm::dvec3& v : loop) original_.emplace(view_.project(v), v);
  };
  add(polygon.outer);
  for (const hsr::Loop3& h : polygon.holes) add(h);
  // The plane relative to the eye: a scene far from the origin keeps its precision.
  offset_from_eye_ = view_.offset_from_eye(polygon.outer, normal_);
}

hsr::Loop3 BackProjector::lift(const clipper::Loop2& loop) const {
  hsr::Loop3 out;
  out.reserve(loop.size());
  for (const clipper::Point2& q : loop) {
    const auto it = original_.find(q);
    if (it != original_.end()) {
      out.push_back(it->second);
    } else if (const auto d = view_.unproject_offset(q, normal_, offset_from_eye_)) {
      out.push_back(view_.eye() + *d);
    }
  }
  return out;
}

hsr::Polygon3 BackProjector::lift(const clipper::PolygonWithHoles2& p) const {
  hsr::Polygon3 out{lift(p.outer), {}};
  for (const clipper::Loop2& h : p.holes) out.holes.push_back(lift(h));
  return out;
}

}  // namespace shadowgen::detail
