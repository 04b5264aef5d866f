#pragma once

// The exact shadow oracle: for each (face, light), the lit region that the spec's
// "Meaning of lit" defines, computed with CGAL's exact kernel (Epeck) independently of
// hsr/ and clipper/. No CGAL type shows here; shadow_oracle.cpp is the only translation
// unit that pays CGAL's compile time.
//
// The construction, all in exact rationals (every input double converts exactly):
//   - a face part's plane is its exact Newell normal n (twice its area vector) through
//     the mean of n·v over its outer vertices: for an exactly planar part, its own plane;
//   - regions live in the part's chart, its plane with the coordinate of n's largest
//     component dropped: an exact affine bijection of the plane that scales areas by
//     |n_k|/|n|, so chart areas are exact and 3D areas are the chart's times |n|/|n_k|
//     (one rounding);
//   - the face F is lit nowhere when it turns its back on the light or sees it edge-on
//     (a light in F's plane), or, for a point light with range, when all of F lies
//     farther than range.end (exact squared distances);
//   - every other part O with area, not exactly coplanar with F and not seeing the light
//     edge-on (a point light in O's plane blocks nothing: a segment touching O only at
//     its end is not blocked), casts: its part strictly between the light and F's plane
//     (the slab 0 < s_F < s_F(light) for a point light, the half-space s_F > 0 for a
//     directional one) is projected from the light onto F's plane. Where O crosses the
//     slab's boundary it is cut exactly first, in O's own chart (for a point light also
//     by the cone from the light over F's chart bounding box, so nothing projects to
//     infinity);
//   - lit(F, L) = F minus the union of the shadows, by CGAL's Boolean set operations.
//
// A face wholly beyond a point light's range.end receives nothing from that light, as the
// spec says, but it still casts shadows: a face that reaches inside range.end gets its
// whole lit region, the shadows of occluders beyond range.end included.

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::test {

// Exact areas of one (face, light), each rounded to double once.
struct ExactLit {
  double face_area = 0.0;     // area of the face (holes removed), summed over its parts
  double lit_area = 0.0;      // area of the exact lit region
  double lit_fraction = 0.0;  // lit_area / face_area from the exact chart areas; 0 for
                              // a face without area
};

// Our lit polygons for one (face, light) compared with the exact lit region.
struct LitComparison {
  double face_area = 0.0;
  double exact_lit_area = 0.0;
  double our_union_area = 0.0;        // exact area of the union of our polygons
  double our_pieces_area = 0.0;       // exact sum of our polygons' areas (overlaps count twice)
  double symmetric_difference = 0.0;  // exact area of (ours Δ exact)
  double outside_face_area = 0.0;     // exact area of (ours − face): lit where no face is
  // Non-empty when a loop of ours is not simple (touches or crosses itself): the
  // polygons are invalid. Such a loop is still measured, by the even-odd rule.
  std::string invalid;
  // Non-empty when our polygons cannot be read at all (a lit polygon on a face without
  // area); the areas above other than face_area and exact_lit_area are then NaN.
  std::string problem;
};

class ShadowOracle {
 public:
  // The scene is copied; regions are computed on first request and kept.
  explicit ShadowOracle(const Scene& scene);
  ~ShadowOracle();
  ShadowOracle(const ShadowOracle&) = delete;
  ShadowOracle& operator=(const ShadowOracle&) = delete;

  ExactLit lit(std::size_t face, std::size_t light) const;

  // `ours` are lit detail polygons of the face (ShadowedScene::lit[face][light]). Each is
  // assigned to the face part whose plane it lies closest to and read in that part's
  // chart (dropping a coordinate of our 3D points is exact).
  LitComparison compare(std::size_t face, std::size_t light,
                        std::span<const hsr::Polygon3> ours) const;

  // The exact lit region rounded to doubles, lifted back onto the face's plane: for
  // pictures and reproducers, not for comparisons.
  std::vector<hsr::Polygon3> lit_polygons(std::size_t face, std::size_t light) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowgen::test
