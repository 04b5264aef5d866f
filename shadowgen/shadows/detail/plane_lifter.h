#pragma once

// Between a face part's plane and its chart (plane_chart.h), relative to a vertex.
//
// Chart coordinates are taken relative to `origin`, a vertex on the plane: far from the
// origin of the scene (1e8) the offsets of nearby points are exact and small, so clipping
// in the chart keeps their precision. Back to 3D: the vertices that came in through
// flatten() by lookup (exact), others by the plane's equation n·d = 0 (it passes through
// the origin vertex) solved for the dropped coordinate, the best-conditioned one (the
// normal's largest component).

#include <unordered_map>
#include <vector>

#include "clipper/polygon.h"
#include "hsr/polygon3.h"
#include "hsr/plane_chart.h"

namespace shadowgen::detail {

class PlaneLifter {
 public:
  PlaneLifter(const hsr::Plane3& plane, const glm::dvec3& origin);

  // Chart coordinates of vertices, remembered so they lift back exactly.
  clipper::Loop2 flatten(const hsr::Loop3& loop);
  clipper::PolygonWithHoles2 flatten(const hsr::Polygon3& polygon);

  // Back to 3D, outer loops counter-clockwise seen from the side the normal points to
  // (the chart keeps orientation only where the dropped normal component is positive).
  std::vector<hsr::Polygon3> lift(const clipper::PolygonSet2& set) const;

  // p − origin for a point of the plane given by its chart coordinates.
  glm::dvec3 offset_on_plane(const clipper::Point2& q) const;
  const glm::dvec3& origin() const { return origin_; }
  const hsr::PlaneChart& chart() const { return chart_; }

 private:
  hsr::Loop3 lift(const clipper::Loop2& loop) const;

  hsr::PlaneChart chart_;
  hsr::Plane3 plane_;
  glm::dvec3 origin_;
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> known_;
};

}  // namespace shadowgen::detail
