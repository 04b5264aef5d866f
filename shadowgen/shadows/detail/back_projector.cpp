#include "back_projector.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace shadowgen::shadows::detail {

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
  anchor_ = polygon.outer.front();
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& v : polygon.outer) mean += v - anchor_;
  offset_from_anchor_ = glm::dot(normal_, mean / static_cast<double>(polygon.outer.size()));
  cast_reach_ = reach_of_cast(polygon);
}

double BackProjector::reach_of_cast(const hsr::Polygon3& polygon) {
  // The window's corners (±1) are image points of a perspective view's fragments too.
  double image = view_.is_perspective() ? 1.0 : 0.0;
  for (const auto& [q, v] : original_) image = std::max({image, std::abs(q.x), std::abs(q.y)});
  if (view_.is_perspective()) {
    for (const glm::dvec3& v : polygon.outer) {
      farthest_ = std::max(farthest_, glm::length(v - view_.eye()));
    }
  }
  return reach_of(image);
}

double BackProjector::reach_of(double image) const {
  const double moved = 16.0 * 0x1p-53 * image;
  if (!view_.is_perspective()) {
    const double sine = std::abs(glm::dot(normal_, view_.forward()));
    return sine > 0.0 ? 2.0 * moved / sine : INFINITY;
  }
  const double height = std::abs(offset_from_eye_);
  return height > 0.0 ? 2.0 * moved * farthest_ * farthest_ / height : INFINITY;
}

glm::dvec3 BackProjector::onto_plane(const glm::dvec3& p) const {
  return p - (glm::dot(normal_, p - anchor_) - offset_from_anchor_) * normal_;
}

hsr::Loop3 BackProjector::lift(const clipper::Loop2& loop) const {
  hsr::Loop3 out;
  out.reserve(loop.size());
  for (const clipper::Point2& q : loop) {
    const auto it = original_.find(q);
    if (it != original_.end()) {
      out.push_back(it->second);
    } else if (const auto d = view_.unproject_offset(q, normal_, offset_from_eye_)) {
      out.push_back(onto_plane(view_.eye() + *d));
    }
  }
  return out;
}

hsr::Polygon3 BackProjector::lift(const clipper::PolygonWithHoles2& p) const {
  hsr::Polygon3 out{lift(p.outer), {}};
  for (const clipper::Loop2& h : p.holes) out.holes.push_back(lift(h));
  return out;
}

}  // namespace shadowgen::shadows::detail
