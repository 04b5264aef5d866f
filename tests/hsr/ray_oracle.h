#pragma once

// The brute-force answer to "which polygon does the eye see through this image point",
// independent of everything hidden-surface removal does: the ray of View::ray_through is
// intersected with every input polygon's plane in 3D, the hit point is tested against
// the polygon in the polygon's own plane, and the hit nearest along View::forward() wins
// (perspective views: only hits at depth >= near count). No image-space geometry, no
// sorting, no clipping.
//
// Planes are Newell's normal of the outer loop through the loop's centroid, computed in
// coordinates relative to the view's eye (orthographic: its centre), so a scene far from
// the origin is as precise here as at it. The inside test works in the plane's chart
// (the two world axes other than the normal's largest component), with the crossing rule
// over the outer loop and the holes. Cost: O(total vertices) per ray.

#include <cstddef>
#include <glm/vec3.hpp>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "clipper/polygon.h"
#include "hsr/polygon3.h"
#include "hsr/view.h"

namespace shadowgen::test {

// Each hit's depth also carries its own rounding bound, which grows as the plane turns
// edge-on to the ray; it widens both tolerances for that hit.
struct RayTolerance {
  // Hits whose depths along View::forward() differ by less are tied (world units).
  double depth = 0.0;
  // A hit closer than this to its polygon's boundary, measured in the polygon's chart,
  // lies on the boundary: the ray may or may not see the polygon there.
  double margin = 0.0;
};

struct RayAnswer {
  // A hit on some polygon's boundary (or, in perspective, at the near plane) is not
  // behind the nearest clear hit: the oracle cannot decide what the ray sees.
  bool ambiguous = false;
  // The polygons seen: every clear hit within RayTolerance::depth of the nearest one.
  // Empty when the ray sees nothing.
  std::vector<std::size_t> nearest;
  double depth = 0.0;  // of the nearest clear hit
};

class RayOracle {
 public:
  RayOracle(std::span<const hsr::Polygon3> polygons, const hsr::View& view, RayTolerance tolerance);

  RayAnswer at(const clipper::Point2& image) const;

  // Depth along View::forward() at which the ray of `image` meets the plane of polygon
  // `index`, inside the polygon or not; nullopt when the ray is parallel to the plane or,
  // in perspective, meets it behind the eye.
  std::optional<double> plane_depth(std::size_t index, const clipper::Point2& image) const;

  // A random point of polygon `index` (world coordinates, on its plane) at least ten
  // margins inside its boundary; nullopt when rejection sampling in the chart fails.
  std::optional<glm::dvec3> interior_point(std::size_t index, std::mt19937_64& rng) const;

 private:
  struct Face {
    bool usable = false;  // the outer loop has area
    glm::dvec3 normal{0.0};
    glm::dvec3 point{0.0};  // on the plane, relative to the eye
    int drop = 2;
    std::vector<clipper::Loop2> chart_loops;
    double xmin = 0.0, xmax = 0.0, ymin = 0.0, ymax = 0.0;
  };
  struct Hit {
    double depth = 0.0;
    double uncertainty = 0.0;  // bound on the rounding error of depth
    bool inside = false;
    double boundary_distance = 0.0;
  };

  struct LocalRay {
    glm::dvec3 origin;  // relative to the eye
    glm::dvec3 direction;
  };

  LocalRay local_ray(const clipper::Point2& image) const;
  std::optional<Hit> hit(const Face& face, const LocalRay& ray, bool measure) const;
  clipper::Point2 to_chart(const Face& face, const glm::dvec3& p) const;

  hsr::View view_;
  RayTolerance tolerance_;
  glm::dvec3 origin_;
  std::vector<Face> faces_;
};

}  // namespace shadowgen::test
