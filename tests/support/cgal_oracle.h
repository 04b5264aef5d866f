#pragma once

// The exact oracle: CGAL's exact kernel (Epeck) behind a header that shows no CGAL type,
// so that only cgal_oracle.cpp pays CGAL's compile time.
//
// Inputs are our double-coordinate polygons; every double converts exactly to the
// kernel's rationals, so the oracle answers for the very same input the clipper saw.
// Orientation of the input loops is free: outer loops are turned counter-clockwise and
// holes clockwise before CGAL sees them (CGAL requires it). Consecutive repeated
// vertices are dropped. The operands must satisfy clip()'s input contract
// (input_problem); a polygon whose hole touches its outer loop inside an edge, which
// CGAL's Polygon_with_holes_2 does not allow, is built as outer loop minus holes. The
// polygons of a set are joined, so a multipolygon is the union of its parts.

#include <array>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <string>

#include "clipper/polygon.h"

namespace shadowgen::test {

using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

// Exact areas, each rounded to double once at the end (relative error below 2^-52).
struct ExactAreas {
  double inside = 0.0;        // area(subject ∩ clip)
  double outside = 0.0;       // area(subject − clip)
  double subject = 0.0;       // area(subject)
  double clip = 0.0;          // area(clip)
  double clip_outside = 0.0;  // area(clip − subject), for the swapped clip
};

// The exact intersection and difference of two regions, kept for further questions.
class ExactOverlay {
 public:
  ExactOverlay(const PolygonSet2& subject, const PolygonSet2& clip);
  ~ExactOverlay();
  ExactOverlay(const ExactOverlay&) = delete;
  ExactOverlay& operator=(const ExactOverlay&) = delete;

  ExactAreas areas() const;

  // Area of the symmetric difference between `ours` and the exact subject ∩ clip
  // (resp. subject − clip). `ours` must pass validity_problem (CGAL's set operations
  // have that precondition); this is the strongest comparison: areas can agree by
  // accident, the symmetric difference cannot.
  double inside_discrepancy(const PolygonSet2& ours) const;
  double outside_discrepancy(const PolygonSet2& ours) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

ExactAreas exact_clip_areas(const PolygonSet2& subject, const PolygonSet2& clip);

// Exact area of a region (the union of the set's polygons), orientation free.
double exact_area(const PolygonSet2& region);

// Exact area enclosed by the given pieces, without any set operation: the sum of
// |area(outer loop)| − Σ |area(hole)| over the polygons, each loop's shoelace sum
// evaluated in rationals. Equals exact_area when the pieces are valid and disjoint;
// unlike a shoelace in doubles it stays exact far from the origin (at 1e8, a double
// shoelace loses everything).
double exact_area_of_pieces(const PolygonSet2& pieces);

// Where the loops of one polygon may touch each other (always at isolated points).
enum class Contacts {
  kCommonVertices,  // only at vertices of both loops: CGAL's rule, and our outputs'
  kAnyPoint,        // also a vertex inside another loop's edge: OGC's rule, clip()'s inputs
};

// "" when CGAL would accept the polygon as a valid Polygon_with_holes_2, otherwise what
// is wrong and where. Valid means: finite coordinates; every loop has at least three
// vertices, no repeated vertex (so no zero-length edge) and no self-intersection; the
// outer loop is counter-clockwise, holes are clockwise; holes lie inside the outer loop
// and outside each other; loops meet only at isolated points, never along an edge, never
// crossing, and (with Contacts::kCommonVertices, CGAL's is_valid_polygon_with_holes
// rule) only at common vertices, never at a vertex inside another loop's edge. All
// decided with exact predicates. Stricter than CGAL in one respect: a loop may not touch
// itself (CGAL allows "relatively simple" loops; our clipper promises simple ones).
std::string validity_problem(const PolygonWithHoles2& polygon,
                             Contacts contacts = Contacts::kCommonVertices);

// Every polygon valid, and the polygons of the set have disjoint interiors: their
// boundaries do not cross or overlap (touching at points is allowed, anywhere) and none
// lies in another's area.
std::string validity_problem(const PolygonSet2& polygons,
                             Contacts contacts = Contacts::kCommonVertices);

// clip()'s input contract (clip.h): orientation free and repeated consecutive vertices
// allowed (both normalised away first), then valid with loops touching at any points.
std::string input_problem(const PolygonSet2& operand);

// The same loops turned as CGAL wants them (outer counter-clockwise, holes clockwise,
// decided exactly), nothing else changed: for checking the validity of inputs whose
// orientation is free. Loops without area keep their orientation.
PolygonSet2 oriented(const PolygonSet2& polygons);

// CGAL's own verdict, CGAL::is_valid_polygon_with_holes with the segment traits: slow,
// for cross-checking validity_problem in the support tests.
bool cgal_accepts(const PolygonWithHoles2& polygon);

// Exact area of the union of several regions that may overlap each other (e.g. the
// images of a scene's polygons). Each polygon must be valid up to orientation.
double exact_union_area(std::span<const PolygonSet2> regions);

// The unions of two collections of regions and the exact area of (∪ a) Δ (∪ b): zero
// exactly when the two cover the same region, whatever the decomposition. Each polygon
// must be valid up to orientation.
struct ExactUnionComparison {
  double a_union = 0.0;
  double b_union = 0.0;
  double symmetric_difference = 0.0;
};
ExactUnionComparison compare_exact_unions(std::span<const PolygonSet2> a,
                                          std::span<const PolygonSet2> b);

// Whether each coordinate of `p` lies within `relative` times its own magnitude of the
// exact crossing P of the lines through a0, a1 and through b0, b1 (not parallel):
// |p.x − P.x| ≤ relative·|P.x| and |p.y − P.y| ≤ relative·|P.y|, decided exactly.
bool near_exact_crossing(const clipper::Point2& p, const clipper::Point2& a0,
                         const clipper::Point2& a1, const clipper::Point2& b0,
                         const clipper::Point2& b1, double relative);

// Whether the closed triangles a and b (corners not collinear) share a point other than
// the corners in `common` (corners of both) and the segment between two of them: CGAL's
// exact intersection of two Triangle_3 (Epeck). With no common corner, whether they meet.
bool exact_triangles_share_more_than(const std::array<glm::dvec3, 3>& a,
                                     const std::array<glm::dvec3, 3>& b,
                                     std::span<const glm::dvec3> common);

}  // namespace shadowgen::test
