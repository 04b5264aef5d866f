#pragma once

// The checks a shadowed database's lit polygons must pass (docs/scene-format.md, "Reading
// rules": a database is checked as strictly as a scene). For one face and one light:
//
//   - every loop has at least 3 vertices;
//   - every vertex lies in the plane of the part it carries (LitPolygon::part), within
//     kPlanarityTolerance × the part's extent (at least the tolerance a face is read
//     with, which takes the smaller of extent and width) + kRoundingReach × (extent +
//     magnitude) + how far the rounding of the part's normal alone can tilt it
//     (Part::tilt_reach);
//   - the lit area (hsr::area, as reports sum it) does not exceed the face's area by more
//     than rounding: kRoundingReach × (extent + magnitude) × the perimeters involved;
//   - on each part, the lit polygons lie inside the part and do not overlap: in the part's
//     plane chart (hsr/plane_chart.h), relative to a vertex of the part, the clipper's
//     part ∩ (union of the lit polygons) has the area of all lit polygons together, up to
//     the same rounding and the clipper's own (clipper::rounding_area_bound). One clip per
//     part and light; a part whose one lit polygon is the part itself needs none.
//
// extent is the largest side of the part's bounding box, magnitude its largest |coordinate|:
// lit vertices are the generator's roundings in the scene's own coordinates, so the
// tolerance follows their magnitude as well as the part's size (a face 1e8 from the origin
// has coordinates rounded to ulps of 1e8). kRoundingReach = 2^-40 is the slack shadow
// generation itself leaves a lit polygon beyond its part (shadows/detail/part_plane.h,
// part_reach): about 8000 ulps, far above rounding, far below any real error.
//
// A part without area (a degenerate face) has no plane; lit polygons on it can only pass
// the area check with an area within rounding of 0.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "clipper/polygon.h"
#include "hsr/plane_chart.h"
#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::scene::detail {

inline constexpr double kRoundingReach = 0x1p-40;

struct LitProblem {
  std::optional<std::size_t> polygon;  // the lit polygon to blame, when one is
  std::string what;
};

class LitChecker {
 public:
  explicit LitChecker(const Face& face);

  // The part whose plane is nearest to the polygon's outer vertices (for lit polygons
  // written without "part"). Among parts as near within rounding (kRoundingReach), as the
  // coplanar parts of a face whose holes cut its region apart are, the first whose
  // bounding box holds the polygon's outer vertices; otherwise the first of the nearest.
  std::size_t nearest_part(const hsr::Polygon3& polygon) const;

  // The first problem of the lit polygons of one light on this face, if any.
  std::optional<LitProblem> check(std::span<const LitPolygon> lit) const;

  // How far the area of `lit` may stray from its exact value by the rounding that
  // generation and clipping leave along boundaries: kRoundingReach × (extent + magnitude)
  // × the perimeters of the face's parts and of `lit` (the bound the area check uses).
  double area_tolerance(std::span<const LitPolygon> lit) const;

 private:
  struct Part {
    const hsr::Polygon3* polygon = nullptr;
    bool flat = false;         // has a plane: a normal, finite and not zero
    glm::dvec3 normal{0.0};    // unit
    glm::dvec3 origin{0.0};    // the outer loop's first vertex
    glm::dvec3 centroid{0.0};  // of the outer loop, relative to origin
    double extent = 0.0;
    glm::dvec3 lo{0.0}, hi{0.0};  // the bounding box
    double reach = 0.0;           // kRoundingReach × (extent + magnitude)
    // How far the rounding of the normal alone can put a point of the part off its plane:
    // Newell's vector is off by ulps of extent² beside its length, twice the area, so a
    // sliver's plane is known only to that tilt, times extent (kRoundingReach × extent³ /
    // (2 × area)). A sliver triangle's own corners once lay 2.2e-5 off it.
    double tilt_reach = 0.0;
    // How far the part's own vertices may lie off its plane: twice its face's vertex
    // rounding (Face::vertex_rounding), the planarity the scene reader allowed a model's
    // face; 0 for a scene's own polygons.
    double vertex_reach = 0.0;
    double perimeter = 0.0;
    hsr::PlaneChart chart;
    clipper::PolygonWithHoles2 flat_polygon;  // in the chart, relative to origin
  };

  double distance_to_plane(const Part& part, const glm::dvec3& p) const;
  clipper::PolygonWithHoles2 to_chart(const Part& part, const hsr::Polygon3& polygon) const;
  std::optional<LitProblem> check_loops_and_planes(std::span<const LitPolygon> lit) const;
  std::optional<LitProblem> check_area(std::span<const LitPolygon> lit) const;
  std::optional<LitProblem> check_inside(std::span<const LitPolygon> lit, std::size_t part) const;
  std::optional<LitProblem> diagnose_inside(std::span<const LitPolygon> lit, std::size_t part,
                                            const std::vector<std::size_t>& on_part,
                                            double tolerance) const;

  std::vector<Part> parts_;
  double face_area_ = 0.0;
  bool several_parts_ = false;
};

}  // namespace shadowgen::scene::detail
