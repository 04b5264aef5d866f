#pragma once

// Triangulation of a polygon with holes in its plane chart, by ear clipping (Eberly,
// "Triangulation by Ear Clipping", Geometric Tools 2002; the ear test of Mapbox's earcut):
// each hole is joined to the outer boundary by a bridge to a visible vertex, rightmost
// holes first, and ears are cut from the single loop that results. Every decision is an
// exact orient2d on the given points; no point is constructed.
//
// Used for non-planar faces: the triangles, taken on the original 3D vertices, are each
// exactly planar. Cost O(n^2) for n vertices in the usual case (each ear test scans the
// loop's non-convex vertices), plus O(n) per bridge candidate tried.

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::clipper {

using Triangle = std::array<std::size_t, 3>;

// loops[0] is the outer loop, the others holes; the loops are valid as check_loops
// (loop_validation.h) accepts them, either orientation. Vertices are numbered through
// the loops in order (the outer loop's first, then each hole's). Triangles run the way
// the outer loop does; consecutive repeated vertices add none. nullopt only when no
// bridge to some hole could be found, which valid input does not produce.
std::optional<std::vector<Triangle>> triangulate(std::span<const clipper::Loop2> loops);

}  // namespace shadowgen::clipper
