#pragma once

// A plane's chart: its points with the coordinate dropped along which the plane's normal
// is largest, and the way back to 3D.
//
// Dropping a coordinate is exact, so an exact predicate on chart points
// (clipper/predicates.h) is an exact statement about the 3D input; for a planar polygon
// the chart is an affine bijection of its plane, so simplicity, containment and
// orientation carry over unchanged. The kept coordinates are taken in cyclic order
// (y, z), (z, x), (x, y), so a loop counter-clockwise seen from the side the normal
// points to is counter-clockwise in the chart exactly when the dropped component is
// positive; where it is negative the chart mirrors the plane.
//
// Tie rule: where the normal's largest components are equal in magnitude (a wall at 45
// degrees), z is dropped before y, and y before x. Every chart of the project is chosen
// by this one rule, so two places that chart the same polygon get the same chart points.
//
// ChartedPlane adds the way back: the vertices that were flattened as known are lifted
// back to themselves exactly (clipping leaves the input's vertices as they were, bit for
// bit); every other chart point (a crossing the clipper made) keeps its kept coordinates
// and gets the dropped one from the plane's equation, written relative to an origin
// vertex on the plane, so that far from the world's origin (1e8) the products do not
// cancel. Its chart coordinates are either the world's own or offsets from the origin
// vertex (ChartFrom).

#include <glm/vec3.hpp>
#include <optional>
#include <unordered_map>
#include <vector>

#include "clipper/polygon.h"
#include "hsr/polygon3.h"

namespace shadowgen::hsr {

struct PlaneChart {
  int dropped_axis = 2;

  int first_kept() const { return (dropped_axis + 1) % 3; }
  int second_kept() const { return (dropped_axis + 2) % 3; }

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

  clipper::Loop2 flatten(const Loop3& loop) const;
  clipper::PolygonWithHoles2 flatten(const Polygon3& polygon) const;
};

// The chart that drops the largest component of `normal`; ties go to z, then y.
PlaneChart chart_facing(const glm::dvec3& normal);

// Where a ChartedPlane's 2D coordinates are measured from.
enum class ChartFrom {
  // The world's kept coordinates as they are: exact, so exact predicates on them decide
  // questions about the 3D points themselves.
  kWorld,
  // The kept coordinates of p − origin: rounded differences, but small and precise near
  // the origin vertex, so that crossings the clipper makes far from the world's origin
  // keep the precision of the polygon's size rather than of its position.
  kOrigin,
};

// a·x + b·y + c on chart points.
using ChartAffine = clipper::Affine2;

// A plane with its chart (chart_facing its normal), both ways.
class ChartedPlane {
 public:
  // The plane through `origin` with `normal` (not zero; a unit normal as plane_of gives).
  ChartedPlane(const glm::dvec3& normal, const glm::dvec3& origin, ChartFrom from);

  const PlaneChart& chart() const { return chart_; }
  const glm::dvec3& normal() const { return normal_; }
  const glm::dvec3& origin() const { return origin_; }
  // Whether the chart mirrors the plane seen from the side the normal points to.
  bool mirrors() const { return normal_[chart_.dropped_axis] < 0.0; }

  // Chart coordinates, not remembered.
  clipper::Point2 flatten(const glm::dvec3& p) const;
  clipper::Loop2 flatten(const Loop3& loop) const;
  clipper::PolygonWithHoles2 flatten(const Polygon3& polygon) const;

  // Chart coordinates of points that lift() is to give back exactly.
  clipper::Loop2 flatten_known(const Loop3& loop);
  clipper::PolygonWithHoles2 flatten_known(const Polygon3& polygon);

  // The known point flattened to q, exactly; any other q: on_plane(q).
  glm::dvec3 lift(const clipper::Point2& q) const;
  // The point of the plane at chart point q: the kept coordinates are q's (plus the
  // origin's, ChartFrom::kOrigin), the dropped one from the plane through the origin.
  glm::dvec3 on_plane(const clipper::Point2& q) const;
  // Polygons back to 3D, loops reversed where the chart mirrors the plane: a polygon
  // counter-clockwise in the chart comes back counter-clockwise seen from the side the
  // normal points to.
  Polygon3 lift(const clipper::PolygonWithHoles2& polygon) const;
  std::vector<Polygon3> lift(const clipper::PolygonSet2& set) const;

  // g · p for the point p = on_plane(q), as an affine function of the chart point q.
  ChartAffine dot_on_plane(const glm::dvec3& g) const;

 private:
  Loop3 lift(const clipper::Loop2& loop) const;

  PlaneChart chart_;
  glm::dvec3 normal_;
  glm::dvec3 origin_;
  ChartFrom from_;
  clipper::Point2 origin_in_chart_;  // the origin's chart point: (0, 0) from itself
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> known_;
};

// A polygon in the chart of its own plane, its vertices known (lift() gives them back
// exactly): the frame in which a face part's pieces (its light-set and sun-hours regions)
// are cut, and lifted back onto it.
struct OwnChart {
  ChartedPlane chart;
  clipper::PolygonWithHoles2 flat;  // the polygon in the chart
};

// None when the polygon has no plane (plane_of gives no normal) or no area.
std::optional<OwnChart> own_chart(const Polygon3& polygon);

}  // namespace shadowgen::hsr
