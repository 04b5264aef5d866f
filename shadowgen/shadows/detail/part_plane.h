#pragma once

// Lit polygons of one face part, set right in the part's own plane chart.
//
// Joining what several light views saw of one face part. A point light looks through up
// to six frusta; a part that spans a seam between two of them is lit in pieces, one per
// view, each cut at the seam in its own view's image. The two cuts are rounded apart, so
// the pieces may overlap or leave a gap a rounding wide, and summing their areas can give
// a lit area above the part's own (a lit fraction of 1.0000000000000029). Here the
// pieces are united in the part's plane chart (hsr/plane_chart.h), exactly as regions: each
// view's pieces minus what earlier views already lit, then merged along shared edges.

#include <span>
#include <vector>

#include "hsr/polygon3.h"

namespace shadowgen::shadows::detail {

// `per_view`: the lit polygons of one part, grouped by the view that saw them. Returns the
// union as polygons with holes in the part's plane, outer loops counter-clockwise seen
// from the side `plane.normal` points to. Vertices that came in are passed through
// unchanged; new ones (where pieces of different views cross) are put on the plane.
std::vector<hsr::Polygon3> unite_views(std::span<const std::vector<hsr::Polygon3>> per_view,
                                       const hsr::Plane3& plane);

// `lit` ∩ `part`, in the part's plane chart. For a part seen almost edge-on by the light,
// where casting image points back onto the plane divides by the sine of a tiny angle and
// a rounded point can land far outside the part: the lit region is the part's at most.
std::vector<hsr::Polygon3> within_part(std::span<const hsr::Polygon3> lit,
                                       const hsr::Polygon3& part, const hsr::Plane3& plane);

// How far generation lets a lit vertex stray beyond its part: 2^-40 of the part's
// bounding box size and position, the rounding of the part itself (the database reader
// allows as much, shadowgen/scene/detail/lit_checks.h).
double part_reach(const hsr::Polygon3& part);

// Whether every vertex of `lit` lies within the part's bounding box, grown by its
// part_reach (then within_part has nothing to cut but roundings).
bool inside_box_of(std::span<const hsr::Polygon3> lit, const hsr::Polygon3& part);

}  // namespace shadowgen::shadows::detail
