#pragma once

// The discretised angular span table of Thakur, Cheng and Miura (sections 3 to 7), for one
// light and one hemisphere of its angular frame (angular_frame.h).
//
// Rows. θ over [θmin, θmax], the global extent of the objects' hidden surfaces (for a closed
// object the extent of its RE loops, on which its silhouette lies: the papers' "θ = 0 ... a
// global minimum in θ" of all loops), is cut into `resolution` equal rows; row k stands for
// its centre θk, where the row plane slices the objects. A point at θ in row k is looked up
// in row k, whatever θ's offset from θk: the discretisation of the shadow volume.
//
// Entries. In each row plane, an object's hidden surface (bounded by its RE loops) is cut
// into pieces running between crossings of its edges: crossings of ridge edges mark the
// beginning and end of a shadow span, crossings of hidden edges (inserted "in duplicate")
// split it where the depth changes face. A pair is one such piece, (φa, ra) to (φb, rb):
// what the papers' table keeps, with the 3D ends so that the depth inside it follows
// exactly ("simple trigonometry"). Every pair lies on one hidden face, so "both elements of
// a pair come from the same RE loop" and coiled loops and holes pair correctly: the pairing
// follows the hidden face between two crossings (the long version's graph of hidden edges
// attached to the RE loop's vertices), not the peak-and-branch traversal and direction
// constraints the papers use to reach the same pairs. A hidden face with holes or not
// convex gives several pieces, paired even-odd along the row; an open edge of a hidden face
// ends a piece as a ridge edge would.
//
// Lookup (section 7's query): the point's (θ, φ, r); no row, or no pair holding φ: lit.
// Pairs are sorted by φa with the running maximum of φb, so a binary search finds the last
// pair starting at or before φ and the walk back stops where no earlier pair reaches φ. The
// point is in shadow at the first pair whose depth at φ is less than r (a relative 1e-9
// margin: a face does not shadow itself where it touches the point), the search stopping
// there (the shadow is the logical OR of all objects' shadows). The depth is that of the
// hidden (far) side of an occluder: a visible face of an object lies before its own hidden
// faces along every ray, so an object does not shadow its own visible faces, except where
// another part of it (a concave object) has a hidden face nearer the light: self-shadowing.

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "angular_frame.h"
#include "hsr/polygon3.h"
#include "ridge_edge_loops.h"

namespace shadowgen::view::detail {

// What a pair's end crosses: a ridge edge, a hidden edge, an open or non-manifold edge of a
// hidden face, or the hemisphere's boundary W = 0 (special case 11.2).
enum class Crossing : unsigned char { kRidge, kHidden, kOpen, kHemisphere };

struct SpanPair {
  double phi0 = 0.0, phi1 = 0.0;   // φa <= φb
  glm::dvec3 a{0.0}, b{0.0};       // local ends (angular_frame.h), at φa and φb
  std::size_t object = kNoObject;  // the occluding object
  Crossing end0 = Crossing::kRidge, end1 = Crossing::kRidge;
};

class AngularSpanTable {
 public:
  // The table of `loops`'s hidden parts (`polygons`, in parallel with loops.facing) in
  // `hemisphere` of `frame`, with `resolution` >= 1 rows.
  AngularSpanTable(const AngularFrame& frame, int hemisphere, const RidgeEdgeLoops& loops,
                   std::span<const hsr::Polygon3> polygons, int resolution);

  int rows() const { return static_cast<int>(rows_.size()); }
  bool empty() const { return !(hi_ >= lo_); }
  double theta_min() const { return lo_; }
  double theta_max() const { return hi_; }
  // The row of θ; -1 outside [θmin, θmax].
  int row_of(double theta) const;
  std::span<const SpanPair> row(int k) const { return rows_[static_cast<std::size_t>(k)]; }
  std::size_t pairs() const;

  // Whether the point with local coordinates `q` (this hemisphere's) is in shadow.
  bool in_shadow(const glm::dvec3& q) const;

 private:
  const AngularFrame* frame_;
  double lo_, hi_, step_ = 0.0;
  std::vector<std::vector<SpanPair>> rows_;
  std::vector<std::vector<double>> reach_;  // running maximum of φb per row
};

}  // namespace shadowgen::view::detail
