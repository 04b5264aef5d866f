#pragma once

// The angular coordinates of Thakur, Cheng and Miura (section 3): a frame fixed to the light
// in which every point has a row coordinate (the papers' θ, sliced into the rows of the
// angular span table), a span coordinate (their φ, along a row) and a depth (their r).
//
// Point light. Axes X, Y, Z at the light, the scene in front of it along −Z (the papers'
// projection plane is the XY plane); W = −Z. Then
//     θ = atan(Y / W),  φ = atan(X / W),  r = sqrt(X² + Y² + Z²),
// which represent one hemisphere (W > 0) uniquely. The papers' special case "light source
// in the scene" (section 11.2) keeps the two hemispheres apart: hemisphere +1 is W > 0 and
// hemisphere −1 mirrors W (W = +Z), each with its own table. A constant-θ row is the plane
// through the light and the X axis, Y cos θ − W sin θ = 0.
//
// Directional light. The light's orthographic frame: X and Y across its direction, W along
// it, θ = Y, φ = X, r = W (one hemisphere, every point in it); a row is the plane Y = θ.

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "shadowgen/model/scene.h"

namespace shadowgen::view::detail {

class AngularFrame {
 public:
  // `toward`: a point the point light's −Z axis aims at (the scene's centre); unused for a
  // directional light.
  AngularFrame(const Light& light, const glm::dvec3& toward)
      : point_(light.type == LightType::kPoint) {
    glm::dvec3 axis = light.direction;
    if (point_) {
      origin_ = light.position;
      axis = toward - light.position;
      if (!(glm::dot(axis, axis) > 0.0)) axis = {0.0, 0.0, -1.0};
    }
    w_ = glm::normalize(axis);
    const glm::dvec3 helper =
        std::abs(w_.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
    x_ = glm::normalize(glm::cross(helper, w_));
    y_ = glm::cross(w_, x_);
  }

  bool point() const { return point_; }
  int hemispheres() const { return point_ ? 2 : 1; }

  // (X, Y, W) of `p` in hemisphere +1 (or −1: W mirrored).
  glm::dvec3 local(const glm::dvec3& p, int hemisphere) const {
    const glm::dvec3 d = p - origin_;
    return {glm::dot(d, x_), glm::dot(d, y_), hemisphere * glm::dot(d, w_)};
  }
  // The hemisphere a point belongs to: +1 where W >= 0.
  int hemisphere_of(const glm::dvec3& p) const {
    return point_ && glm::dot(p - origin_, w_) < 0.0 ? -1 : 1;
  }

  // θ, φ, r of a local point.
  double row(const glm::dvec3& q) const { return point_ ? std::atan2(q.y, q.z) : q.y; }
  double span(const glm::dvec3& q) const { return point_ ? std::atan2(q.x, q.z) : q.x; }
  double depth(const glm::dvec3& q) const { return point_ ? glm::length(q) : q.z; }

  // The signed side of a local point from the row plane at θ = `theta`.
  double side(const glm::dvec3& q, double theta) const {
    return point_ ? q.y * std::cos(theta) - q.z * std::sin(theta) : q.y - theta;
  }

  // The depth at span coordinate `phi` of the segment from `a` to `b` (local points in one
  // row plane): where the ray of the row at φ meets it ("simple trigonometry": a line
  // through the light for a point light, the line X = φ for a directional one).
  double depth_at(const glm::dvec3& a, const glm::dvec3& b, double phi) const {
    double fa, fb;
    if (point_) {
      const double c = std::cos(phi), s = std::sin(phi);
      fa = a.x * c - a.z * s;
      fb = b.x * c - b.z * s;
    } else {
      fa = a.x - phi;
      fb = b.x - phi;
    }
    double t = fa == fb ? 0.0 : fa / (fa - fb);
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    if (fa == fb) return std::min(depth(a), depth(b));
    return depth(a + t * (b - a));
  }

 private:
  bool point_;
  glm::dvec3 origin_{0.0};
  glm::dvec3 x_{1.0, 0.0, 0.0}, y_{0.0, 1.0, 0.0}, w_{0.0, 0.0, -1.0};
};

}  // namespace shadowgen::view::detail
