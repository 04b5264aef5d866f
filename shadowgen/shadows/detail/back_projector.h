#pragma once

// From a light's image back onto a face part's plane: the lit regions found in the image
// become lit detail polygons in the scene's coordinates.

#include <unordered_map>

#include "clipper/polygon.h"
#include "hsr/polygon3.h"
#include "hsr/view.h"

namespace shadowgen::shadows::detail {

// Maps image points of one view back onto a part's plane: the part's own vertices come
// back exactly, other points are cast onto the plane along the light's ray.
//
// The cast is computed from the eye, so it rounds relative to the light's distance: a
// face 1e-9 across, 3 from a lamp, got points 4e-16 off its plane, 200 times what the
// face's own size and position round to, and the database did not read back. Each cast
// point is therefore set back onto the plane along its normal, relative to the part's
// first vertex: what stays off the plane is rounding of the part's own size and position
// (docs/scene-format.md: lit polygons lie in their face's plane within rounding). The
// move is along the normal, by about 2^-52 of the light's distance, far below the
// point's rounding within the plane, which is the image's.
class BackProjector {
 public:
  BackProjector(const hsr::View& view, const hsr::Polygon3& polygon, const hsr::Plane3& plane);

  // How far the image's rounding, cast back, can move a point within the plane. Image
  // points are off by up to 16 u of the largest image coordinate (u = 2^-53: a hot pixel
  // of 12 u, clipper/clip.h, and the projection's own rounding), and a move δ in the image
  // moves the cast point by at most 2δ·D²/h in a perspective view (D the farthest vertex's
  // distance from the eye, h the eye's height over the plane) and by 2δ/|n·forward| in an
  // orthographic one. For a small face far from a lamp this exceeds the face's own
  // rounding, and lit polygons can bulge out of the face by it. The plane itself is taken
  // as exact: hsr::plane_of gives its normal to a few ulps, a sliver's too (a sliver's
  // plane once came out 5.6e-7 off, and its lit polygon lay 480 of its widths beside it).
  double cast_reach() const { return cast_reach_; }
  // The same bound for image points of magnitude at most `image` (the points at hand, such
  // as a lit region's clipped to a perspective view's window, rather than the part's
  // vertices, which beside the eye project far out or, on its plane, to infinity).
  double reach_of(double image) const;

  // A point whose ray misses the plane (parallel to it) is left out.
  hsr::Loop3 lift(const clipper::Loop2& loop) const;
  hsr::Polygon3 lift(const clipper::PolygonWithHoles2& p) const;

 private:
  double reach_of_cast(const hsr::Polygon3& polygon);  // sets farthest_
  glm::dvec3 onto_plane(const glm::dvec3& p) const;

  const hsr::View& view_;
  glm::dvec3 normal_;
  double offset_from_eye_ = 0.0;
  glm::dvec3 anchor_{0.0};           // the part's first vertex
  double offset_from_anchor_ = 0.0;  // the plane: normal·(p − anchor) = offset_from_anchor_
  double cast_reach_ = 0.0;
  double farthest_ = 0.0;  // perspective: the part's farthest outer vertex from the eye
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> original_;
};

}  // namespace shadowgen::shadows::detail
