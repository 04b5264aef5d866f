#pragma once

// A view: where hidden-surface removal looks from, and how 3D maps to its image plane.
//
// Image coordinates are 2D doubles. Orthographic: lengths along two axes perpendicular to
// the direction, measured from a centre point the caller chooses near the scene (the
// paper's "fitting the environment into the viewbox": far from the origin, coordinates
// relative to a nearby centre keep their precision). Perspective: (x/z, y/z) in the eye's
// frame, z along the forward axis; the view sees the frustum z >= near,
// |x/z| <= tan(fov/2)·aspect, |y/z| <= tan(fov/2).
//
// Depth is compared through "nearness", a function that grows toward the eye and is
// affine in image coordinates on any plane: −z for orthographic views, 1/z for
// perspective ones. So a fragment with its parent's plane knows its exact depth anywhere.

#include <glm/vec3.hpp>
#include <optional>

#include "clipper/polygon.h"
#include "hsr/polygon3.h"

namespace shadowgen::hsr {

// nearness(x, y) = a·x + b·y + c on one plane.
using Nearness = clipper::Affine2;

struct Ray3 {
  glm::dvec3 origin;
  glm::dvec3 direction;  // not normalised
};

class View {
 public:
  // Looking along `direction` (need not be unit length); image coordinates measured from
  // `center`.
  static View orthographic(const glm::dvec3& direction, const glm::dvec3& center);
  // From `eye` looking along `forward`, `up` fixing the roll (it need not be orthogonal to
  // forward, only not parallel). fov_deg is the full vertical angle, 0 < fov < 180.
  static View perspective(const glm::dvec3& eye, const glm::dvec3& forward, const glm::dvec3& up,
                          double fov_deg, double near, double aspect = 1.0);

  bool is_perspective() const { return perspective_; }
  const glm::dvec3& eye() const { return eye_; }
  const glm::dvec3& forward() const { return forward_; }
  double near() const { return near_; }

  // Eye-frame coordinates (right, up, forward) of p, relative to the eye (perspective) or
  // the centre (orthographic).
  glm::dvec3 to_eye_frame(const glm::dvec3& p) const;
  // Image point of p; for perspective views p must lie in front of the eye.
  clipper::Point2 project(const glm::dvec3& p) const;
  // Image point of eye() + offset, from the offset itself: for points constructed
  // relative to the eye, which a scene far from the origin keeps precise.
  clipper::Point2 project_offset(const glm::dvec3& offset) const;
  // The ray of points that project to `image`, from the eye (perspective) or from the
  // plane through the centre perpendicular to the direction (orthographic).
  Ray3 ray_through(const clipper::Point2& image) const;
  // The point of `plane` seen at `image`; nullopt when the ray is parallel to the plane.
  std::optional<glm::dvec3> unproject(const clipper::Point2& image, const Plane3& plane) const;
  // The same, for points given relative to the eye (the centre, for orthographic views):
  // the plane normal · d = offset_from_eye, and the result is d, the point's offset from
  // the eye. Far from the origin this keeps the precision the absolute form loses in
  // normal · origin.
  std::optional<glm::dvec3> unproject_offset(const clipper::Point2& image, const glm::dvec3& normal,
                                             double offset_from_eye) const;
  // Nearness on `plane`, or nullopt when the plane is seen edge-on (it contains the
  // view direction, or the eye; for an orthographic view, within the rounding of the
  // normal and the view's frame, 2^-49, of containing it).
  std::optional<Nearness> nearness_on(const Plane3& plane) const;
  // The same for the plane normal · d = offset_from_eye of points eye() + d. Far from the
  // origin (1e8) plane.offset − normal · eye cancels and loses what decides the order of
  // two faces meeting at an edge; offsets formed from nearby vertices keep it.
  std::optional<Nearness> nearness_on(const glm::dvec3& normal, double offset_from_eye) const;
  // The offset from the eye of the plane through `loop` with `normal`, through the loop's
  // mean offset from the eye (exact differences for vertices near it).
  double offset_from_eye(const Loop3& loop, const glm::dvec3& normal) const;
  // Nearness of a 3D point, comparable with nearness_on(...).at(...).
  double nearness_of(const glm::dvec3& p) const;
  // The image window of a perspective view (its frustum's sides); none for orthographic.
  std::optional<clipper::PolygonWithHoles2> window() const;

 private:
  bool perspective_ = false;
  glm::dvec3 eye_{0.0};  // the centre, for orthographic views
  glm::dvec3 right_{1.0, 0.0, 0.0};
  glm::dvec3 up_{0.0, 1.0, 0.0};
  glm::dvec3 forward_{0.0, 0.0, 1.0};
  double near_ = 0.0;
  double half_height_ = 1.0;  // tan(fov/2)
  double aspect_ = 1.0;
};

}  // namespace shadowgen::hsr
