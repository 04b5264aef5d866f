#include "shadowgen/view/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "shadowgen/model/view_limits.h"

namespace shadowgen {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// `up` unless it lies along `forward` (shadowgen/model/view_limits.h); then +y, or +z for
// a view along y.
glm::dvec3 usable_up(const glm::dvec3& forward, const glm::dvec3& up) {
  if (!along_sight(forward, up)) return up;
  const glm::dvec3 y(0.0, 1.0, 0.0);
  if (!along_sight(forward, y)) return y;
  return {0.0, 0.0, 1.0};
}

template <typename Visit>
void for_each_vertex(const Scene& scene, Visit&& visit) {
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      for (const glm::dvec3& p : part.outer) visit(p);
      for (const hsr::Loop3& hole : part.holes) {
        for (const glm::dvec3& p : hole) visit(p);
      }
    }
  }
}

double bounding_diagonal(const Scene& scene) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for_each_vertex(scene, [&](const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  });
  return lo.x <= hi.x ? glm::length(hi - lo) : 0.0;
}

}  // namespace

Camera camera_from_view(const ViewSpec& spec, bool orthographic) {
  Camera camera;
  camera.eye = spec.eye;
  camera.target = spec.target;
  camera.up = spec.up;
  camera.fov_deg = spec.fov_deg;
  camera.orthographic = orthographic;
  return camera;
}

CameraView::CameraView(const Camera& camera, const Scene& scene, int width, int height)
    : width_(width), height_(height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("the picture's width and height must be positive");
  }
  if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up)) {
    throw std::invalid_argument("the camera's eye, target and up must be finite");
  }
  const glm::dvec3 direction = camera.target - camera.eye;
  if (!(glm::length(direction) > 0.0)) {
    throw std::invalid_argument("the camera's eye and target must differ");
  }
  const glm::dvec3 forward = glm::normalize(direction);
  const glm::dvec3 up = usable_up(forward, camera.up);
  const double w = static_cast<double>(width), h = static_cast<double>(height);

  if (!camera.orthographic) {
    if (const std::optional<std::string> problem = range_problem(camera.fov_deg, fov_range())) {
      throw std::invalid_argument("the field of view " + *problem);
    }
    double near = camera.near;
    if (near <= 0.0) {
      const double diagonal = bounding_diagonal(scene);
      near = diagonal > 0.0 && std::isfinite(diagonal) ? 1e-5 * diagonal : 1e-9;
    }
    view_ = hsr::View::perspective(camera.eye, forward, up, camera.fov_deg, near, w / h);
    // The view's frame is built from the same forward and up: no rotation.
    scale_ = 0.5 * h / std::tan(0.5 * camera.fov_deg * std::numbers::pi / 180.0);
    tx_ = 0.5 * w;
    ty_ = 0.5 * h;
    return;
  }

  if (camera.pixels_per_unit != 0.0) {
    if (const std::optional<std::string> problem =
            range_problem(camera.pixels_per_unit, scale_range())) {
      throw std::invalid_argument("the scale " + *problem);
    }
  }
  view_ = hsr::View::orthographic(forward, camera.target);
  // hsr's orthographic view chooses its own roll; measure the angle between its image x
  // axis and the camera's right. The probe is scaled to the target's magnitude (a power of
  // two) so that target + probe − target loses nothing that matters.
  const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
  const double magnitude = std::max(
      {1.0, std::abs(camera.target.x), std::abs(camera.target.y), std::abs(camera.target.z)});
  const double probe = std::exp2(std::ceil(std::log2(magnitude)));
  const glm::dvec3 seen = view_.to_eye_frame(camera.target + probe * right) / probe;
  const double length = std::hypot(seen.x, seen.y);
  cos_ = seen.x / length;
  sin_ = seen.y / length;
  tx_ = 0.5 * w;
  ty_ = 0.5 * h;

  scale_ = camera.pixels_per_unit;
  if (scale_ == 0.0) {
    double max_x = 0.0, max_y = 0.0;
    for_each_vertex(scene, [&](const glm::dvec3& p) {
      const clipper::Point2 q = view_.project(p);
      max_x = std::max(max_x, std::abs(cos_ * q.x + sin_ * q.y));
      max_y = std::max(max_y, std::abs(sin_ * q.x - cos_ * q.y));
    });
    const double fit_x = max_x > 0.0 ? 0.5 * w / max_x : INFINITY;
    const double fit_y = max_y > 0.0 ? 0.5 * h / max_y : INFINITY;
    scale_ = std::min(fit_x, fit_y);
    scale_ = std::isfinite(scale_) ? 0.95 * scale_ : 1.0;
  }
  pixels_per_unit_ = scale_;
}

clipper::Point2 CameraView::to_pixels(const clipper::Point2& image) const {
  return {tx_ + scale_ * (cos_ * image.x + sin_ * image.y),
          ty_ + scale_ * (sin_ * image.x - cos_ * image.y)};
}

clipper::Point2 CameraView::from_pixels(const clipper::Point2& pixel) const {
  // R is its own inverse.
  const double x = (pixel.x - tx_) / scale_, y = (pixel.y - ty_) / scale_;
  return {cos_ * x + sin_ * y, sin_ * x - cos_ * y};
}

clipper::PolygonWithHoles2 CameraView::window() const {
  const double w = static_cast<double>(width_), h = static_cast<double>(height_);
  // Pixel corners clockwise on screen (y down) are counter-clockwise in the image.
  return {
      {from_pixels({0.0, h}), from_pixels({w, h}), from_pixels({w, 0.0}), from_pixels({0.0, 0.0})},
      {}};
}

}  // namespace shadowgen
