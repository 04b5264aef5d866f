#pragma once

// From a light's image back onto a face part's plane: the lit regions found in the image
// become lit detail polygons in the scene's coordinates.

#include <unordered_map>

#include "clipper/polygon.h"
#include "hsr/polygon3.h"
#include "hsr/view.h"

namespace shadowgen::detail {

// Maps image points of one view back onto a part's plane: the part's own vertices come
// back exactly, other points are cast onto the plane along the light's ray.
class BackProjector {
 public:
  BackProjector(const hsr::View& view, const hsr::Polygon3& polygon, const hsr::Plane3& plane);

  // A point whose ray misses the plane (parallel to it) is left out.
  hsr::Loop3 lift(const clipper::Loop2& loop) const;
  hsr::Polygon3 lift(const clipper::PolygonWithHoles2& p) const;

 private:
  const hsr::View& view_;
  glm::dvec3 normal_;
  double offset_from_eye_ = 0.0;
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> original_;
};

}  // namespace shadowgen::detail
