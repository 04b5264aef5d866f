#pragma once

// The first step of triangulate(): a polygon with holes as one ring (Eberly,
// "Triangulation by Ear Clipping", Geometric Tools 2002). Each hole is joined to the
// outer boundary by a bridge to a visible vertex, walked both ways, rightmost holes
// first; a hole that touches the boundary is spliced in where it touches. Every decision
// is an exact orient2d on the given points.

#include <cstddef>
#include <optional>
#include <span>

#include "clipper/polygon.h"
#include "detail/node_ring.h"

namespace shadowgen::clipper::detail {

struct BridgedPolygon {
  NodeRings rings;
  // A node of the one ring, counter-clockwise; kNoNode when the outer loop has fewer than
  // three distinct vertices.
  std::size_t start = kNoNode;
  bool flipped = false;  // the outer loop was clockwise
};

// loops as triangulate() takes them. nullopt when no bridge to some hole was found.
std::optional<BridgedPolygon> bridge_holes(std::span<const Loop2> loops);

}  // namespace shadowgen::clipper::detail
