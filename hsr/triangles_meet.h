#pragma once

// Exact contact tests of triangles in space, for telling whether a closed surface touches
// or crosses itself (shadowgen/shadows/detail/closed_solids.h). Every decision is the sign
// of an orient3d or orient2d (clipper/predicates.h) on the corners themselves; no point
// is constructed. Triangles are closed and must not be degenerate (their corners not
// collinear).

#include <array>
#include <glm/vec3.hpp>

namespace shadowgen::hsr {

using Triangle3 = std::array<glm::dvec3, 3>;

// Whether the corners are collinear (exact).
bool degenerate(const Triangle3& t);

// Whether the closed segment p-q (p ≠ q) and the triangle share a point.
bool segment_meets_triangle(const glm::dvec3& p, const glm::dvec3& q, const Triangle3& t);

// Whether the two triangles share a point.
bool triangles_meet(const Triangle3& a, const Triangle3& b);

// Whether two triangles meet anywhere but where neighbours on a surface must, given the
// corners they have in common (equal coordinates): with no common corner, anywhere; with
// one, anywhere else than at it; with two, anywhere off their common edge, and, were
// they coplanar, anywhere at all but on opposite sides of it (folded onto each other they
// overlap); with three, they overlap. `coplanar`: the caller knows them to lie exactly in
// one plane (shadowgen/shadows/detail/coplanar_groups.h decides that exactly), and every
// question is settled in the plane's projection, where orient3d would have to find each
// of its determinants exactly zero the slow way.
bool triangles_overlap_beyond_shared(const Triangle3& a, const Triangle3& b, bool coplanar = false);

}  // namespace shadowgen::hsr
