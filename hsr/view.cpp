#include "hsr/view.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

namespace shadowgen::hsr {
namespace {

// Below this |normal · forward| an orthographic view cannot tell which way a plane faces
// it: the dot product of two unit vectors rounds by up to 3u, a unit normal from plane_of
// is a few ulps off the exact one (hsr/polygon3.h), and the view's frame as much again
// (u = 2^-53). Such a plane is seen edge-on: its image, each vertex projected as it is, is
// thinner than the rounding of its depth extent, and a quad twisted by the rounding of its
// vertices projects to a bowtie.
constexpr double kEdgeOnSine = 16.0 * 0x1p-53;

// A right-handed frame (right, up, forward) with forward along `direction`.
void make_frame(const glm::dvec3& direction, const glm::dvec3& up_hint, glm::dvec3& right,
                glm::dvec3& up, glm::dvec3& forward) {
  const double length = glm::length(direction);
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw std::invalid_argument("view direction must be finite and non-zero");
  }
  forward = direction / length;
  glm::dvec3 hint = up_hint;
  if (!(glm::length(glm::cross(hint, forward)) > 1e-12 * glm::length(hint))) {
    // No usable hint: take the world axis least aligned with forward.
    const glm::dvec3 a = glm::abs(forward);
    hint = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
           : a.y <= a.z             ? glm::dvec3(0, 1, 0)
                                    : glm::dvec3(0, 0, 1);
  }
  // Image x to the right and y up as seen looking along forward.
  right = glm::normalize(glm::cross(forward, hint));
  up = glm::cross(right, forward);
}

}  // namespace

View View::orthographic(const glm::dvec3& direction, const glm::dvec3& center) {
  View v;
  v.perspective_ = false;
  v.eye_ = center;
  make_frame(direction, glm::dvec3(0, 0, 1), v.right_, v.up_, v.forward_);
  return v;
}

View View::perspective(const glm::dvec3& eye, const glm::dvec3& forward, const glm::dvec3& up,
                       double fov_deg, double near, double aspect) {
  if (!(fov_deg > 0.0 && fov_deg < 180.0)) {
    throw std::invalid_argument("field of view must lie strictly between 0 and 180 degrees");
  }
  if (!(near > 0.0) || !std::isfinite(near)) {
    throw std::invalid_argument("near distance must be positive and finite");
  }
  if (!(aspect > 0.0) || !std::isfinite(aspect)) {
    throw std::invalid_argument("aspect ratio must be positive and finite");
  }
  View v;
  v.perspective_ = true;
  v.eye_ = eye;
  v.near_ = near;
  v.aspect_ = aspect;
  v.half_height_ = std::tan(0.5 * fov_deg * std::numbers::pi / 180.0);
  make_frame(forward, up, v.right_, v.up_, v.forward_);
  return v;
}

glm::dvec3 View::to_eye_frame(const glm::dvec3& p) const {
  const glm::dvec3 d = p - eye_;
  return {glm::dot(d, right_), glm::dot(d, up_), glm::dot(d, forward_)};
}

clipper::Point2 View::project(const glm::dvec3& p) const { return project_offset(p - eye_); }

clipper::Point2 View::project_offset(const glm::dvec3& d) const {
  const glm::dvec3 e{glm::dot(d, right_), glm::dot(d, up_), glm::dot(d, forward_)};
  if (perspective_) return {e.x / e.z, e.y / e.z};
  return {e.x, e.y};
}

Ray3 View::ray_through(const clipper::Point2& image) const {
  if (perspective_) return {eye_, right_ * image.x + up_ * image.y + forward_};
  return {eye_ + right_ * image.x + up_ * image.y, forward_};
}

std::optional<glm::dvec3> View::unproject(const clipper::Point2& image, const Plane3& plane) const {
  const Ray3 ray = ray_through(image);
  const double denom = glm::dot(plane.normal, ray.direction);
  if (denom == 0.0) return std::nullopt;
  const double t = (plane.offset - glm::dot(plane.normal, ray.origin)) / denom;
  return ray.origin + t * ray.direction;
}

std::optional<glm::dvec3> View::unproject_offset(const clipper::Point2& image,
                                                 const glm::dvec3& normal,
                                                 double offset_from_eye) const {
  if (perspective_) {
    const glm::dvec3 d = right_ * image.x + up_ * image.y + forward_;
    const double denom = glm::dot(normal, d);
    if (denom == 0.0) return std::nullopt;
    return (offset_from_eye / denom) * d;
  }
  const glm::dvec3 across = right_ * image.x + up_ * image.y;
  const double denom = glm::dot(normal, forward_);
  if (denom == 0.0) return std::nullopt;
  return across + ((offset_from_eye - glm::dot(normal, across)) / denom) * forward_;
}

std::optional<Nearness> View::nearness_on(const Plane3& plane) const {
  return nearness_on(plane.normal, plane.offset - glm::dot(plane.normal, eye_));
}

std::optional<Nearness> View::nearness_on(const glm::dvec3& normal, double rel) const {
  const double nr = glm::dot(normal, right_);
  const double nu = glm::dot(normal, up_);
  const double nf = glm::dot(normal, forward_);
  // rel: the plane relative to the eye (or centre), n·(p − eye) = rel.
  if (perspective_) {
    // p = eye + z (x right + y up + forward): n·p = offset gives
    // 1/z = (x nr + y nu + nf) / rel.
    if (rel == 0.0) return std::nullopt;
    return Nearness{nr / rel, nu / rel, nf / rel};
  }
  // p = centre + x right + y up + z forward: z = (rel − x nr − y nu) / nf, nearness −z.
  if (!(std::fabs(nf) > kEdgeOnSine)) return std::nullopt;
  return Nearness{nr / nf, nu / nf, -rel / nf};
}

double View::offset_from_eye(const Loop3& loop, const glm::dvec3& normal) const {
  if (loop.empty()) return 0.0;
  glm::dvec3 mean(0.0);
  for (const glm::dvec3& v : loop) mean += v - eye_;
  return glm::dot(normal, mean / static_cast<double>(loop.size()));
}

double View::nearness_of(const glm::dvec3& p) const {
  const double z = glm::dot(p - eye_, forward_);
  return perspective_ ? 1.0 / z : -z;
}

std::optional<clipper::PolygonWithHoles2> View::window() const {
  if (!perspective_) return std::nullopt;
  const double h = half_height_, w = half_height_ * aspect_;
  return clipper::PolygonWithHoles2{{{-w, -h}, {w, -h}, {w, h}, {-w, h}}, {}};
}

}  // namespace shadowgen::hsr
