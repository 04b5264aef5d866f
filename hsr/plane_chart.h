#pragma once

// A face's plane chart: its points with the coordinate dropped along which the face's
// normal is largest. Dropping a coordinate is exact, so an exact predicate on chart points
// (clipper/predicates.h) is an exact statement about the 3D input; for a planar face the
// chart is an affine bijection of its plane, so simplicity, containment and orientation
// carry over unchanged. The kept coordinates are taken in cyclic order (y, z), (z, x),
// (x, y), so a loop counter-clockwise seen from the side the normal points to is
// counter-clockwise in the chart exactly when the dropped component is positive.

#include <cmath>
#include <glm/vec3.hpp>

#include "clipper/point.h"

namespace shadowgen::hsr {

struct PlaneChart {
  int dropped_axis = 2;

  clipper::Point2 operator()(const glm::dvec3& p) const {
    switch (dropped_axis) {
      case 0:
        return {p.y, p.z};
      case 1:
        return {p.z, p.x};
      default:
        return {p.x, p.y};
    }
  }
};

// The chart that drops the largest component of `normal` (ties go to z, then y).
inline PlaneChart chart_facing(const glm::dvec3& normal) {
  const double ax = std::abs(normal.x);
  const double ay = std::abs(normal.y);
  const double az = std::abs(normal.z);
  if (az >= ax && az >= ay) return {2};
  return {ay >= ax ? 1 : 0};
}

}  // namespace shadowgen::hsr
