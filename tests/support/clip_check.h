#pragma once

// One clip measured against the exact oracle, in both argument orders: what every
// oracle suite of the clipper asks of a case. The measurements are absolute; each suite
// states its own tolerance and relates them to the operands' areas.

#include <string>

#include "clipper/clip.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen::test {

struct ClipCheck {
  ExactAreas exact;
  clipper::ClipResult forward;  // clip(subject, clip)
  clipper::ClipResult swapped;  // clip(clip, subject)

  // |exact area of our pieces − exact answer|; the areas of our pieces are evaluated
  // exactly too (exact_area_of_pieces), so only the clipper's own error is measured.
  double inside_error = 0.0;        // forward.inside vs subject ∩ clip
  double outside_error = 0.0;       // forward.outside vs subject − clip
  double conservation_error = 0.0;  // |inside + outside − subject|, forward
  double swapped_inside_error = 0.0;
  double swapped_outside_error = 0.0;  // swapped.outside vs clip − subject
  double swapped_conservation_error = 0.0;
  double swap_mismatch = 0.0;  // |area(forward.inside) − area(swapped.inside)|

  // Areas of the symmetric differences with the exact pieces, when asked for and the
  // pieces are valid (otherwise -1).
  double inside_discrepancy = -1.0;
  double outside_discrepancy = -1.0;

  // First validity problem of an output piece ("" if none), naming which result.
  std::string invalid;
  // When invalid: CGAL's is_valid_polygon_with_holes on the rejected polygons of that run.
  std::string cgal_opinion;
  // The clipper threw (it should not for valid input).
  std::string exception;

  // Largest error of the forward run (inside, outside, conservation).
  double forward_error() const;
  // Largest of all the area errors above, both orders and the mismatch.
  double worst_error() const;

  // "" when the case passes: no exception, every piece valid, the forward
  // errors and the swap mismatch within forward_bound, the swapped errors within
  // swapped_bound (bounds are absolute areas). Otherwise the first reason.
  std::string failure(double forward_bound, double swapped_bound) const;
};

struct ClipCheckOptions {
  bool swapped = true;                // also run clip(clip, subject)
  bool symmetric_difference = false;  // also measure the symmetric differences (slower)
};

ClipCheck check_clip(const clipper::PolygonSet2& subject, const clipper::PolygonSet2& clip,
                     const ClipCheckOptions& options = {});

// An upper bound on the area errors, which the suites hold the clipper to: every
// constructed point taken to lie within
//     δ_P = 4u·min(|a1 − a0|, |b1 − b0|) + u·|P|  ≤  δ = u·(4ℓ + R),   u = 2^-53,
// of the exact crossing P, where ℓ is the longest edge of either operand and R the
// largest |P| of their vertices (a crossing lies on an edge, so |P| ≤ R), the error of a
// crossing found along its shorter edge; input vertices unchanged. That is tighter than
// what clip.h promises in general (each coordinate within 5u of its magnitude, and a hot
// pixel of six ulps where features are narrower than one), which the suites' inputs,
// without such features, do not need. Moving one vertex by d changes a polygon's area
// by ½|d × (next − prev)| ≤ ½|d|·(sum of its two edges' lengths), so the area of a set
// of pieces is off by at most δ × (their total boundary length), to first order. The
// inside pieces' boundary runs along ∂S and ∂C, each part at most once, so it is at most
// per(S) + per(C); so is the outside pieces'. Hence
//     B = 2·δ·(per(S) + per(C))
// bounds the inside and outside errors, their sum (inside + outside = subject) and the
// mismatch of the two argument orders; the factor 2 also absorbs the second-order terms
// (δ/ℓ is tiny). Relative to the subject's area this is about 2u·R·(per S + per C)/area(S):
// far from the origin R dominates.
double area_error_bound(const clipper::PolygonSet2& subject, const clipper::PolygonSet2& clip);

// The case and the measurements, for a failure message: the operands as WKT with 17
// digits (paste them into a regression test), the areas, the errors, the problems.
std::string describe(const ClipCheck& check, const clipper::PolygonSet2& subject,
                     const clipper::PolygonSet2& clip);

}  // namespace shadowgen::test
