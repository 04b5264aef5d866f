#pragma once

// Ridge edges and ridge-edge (RE) loops, after Thakur and Cheng ("ridge edge loops", long
// version, section 2) and Thakur, Cheng and Miura (section 2): the edges of an object with
// exactly one adjacent face visible from the light and one hidden, which form closed loops
// on a closed object and bound its shadow volume.
//
// Objects. The parts the light takes into account (light_scope.h: all but kLeftOut) that
// have a plane are joined into objects through shared edges: two parts share an edge where
// a loop edge of each (outer loop or hole) joins the same two vertices, vertices being the
// same where their coordinates are equal bit for bit (a closed box written as six polygons
// with shared corners is one object).
//
// Visible and hidden. A face is visible (the papers' footnote) when its outward (front)
// normal makes a negative dot product with the ray from the light to any point of it: for
// a point light the light on the front side of its plane, for a directional light the
// direction against the normal. A part the light reaches the front of (kFacing) is visible;
// kTurnedAway, and a kOccluder turned away or edge-on, are hidden.
//
// Edges. One adjacent part: open (a dangling face, an open model's border). Two: ridge
// (one visible, one hidden), hidden (both hidden) or visible (both visible). More than
// two: non-manifold. The papers consider closed 3-manifolds only ("each edge is shared by
// exactly two faces ... no dangling edges and dangling faces"): open and non-manifold
// edges are never ridge edges here.
//
// Loops. Each ridge edge is directed as its visible face's loop runs along it (front faces
// run counter-clockwise: the papers' fixed traversal direction with respect to the visible
// faces' outward normals), and the loops are followed edge to edge: at a vertex where
// several ridge edges meet (loops joined through a vertex), the first unused one leaving it
// is taken. On a closed object every loop closes (the papers' proof: an even number of
// ridge edges meets at every vertex); where an object is not closed a chain may end at a
// vertex with no unused ridge edge leaving it, and is kept as an open chain.

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/light_scope.h"

namespace shadowgen::view::detail {

inline constexpr std::size_t kNoObject = static_cast<std::size_t>(-1);

enum class EdgeKind : unsigned char { kRidge, kHidden, kVisible, kOpen, kNonManifold };

enum class Facing : unsigned char {
  kLeftOut,  // left out by the light (kLeftOut) or without a plane: in no object
  kVisible,  // front side toward the light
  kHidden,   // turned away from the light or edge-on
};

struct MeshEdge {
  std::size_t v0 = 0, v1 = 0;      // vertex indices, v0 < v1
  std::vector<std::size_t> parts;  // adjacent parts (indices into the parts given)
  EdgeKind kind = EdgeKind::kOpen;
};

struct RidgeLoop {
  std::size_t object = kNoObject;
  std::vector<std::size_t> vertices;  // in order; closed: the last joins the first
  bool closed = true;
};

struct RidgeEdgeLoops {
  std::vector<glm::dvec3> vertices;
  std::vector<MeshEdge> edges;
  std::vector<Facing> facing;               // per part
  std::vector<std::size_t> object_of_part;  // per part; kNoObject where left out
  std::size_t objects = 0;
  // Per part, per loop (outer first, then holes), the edge from vertex i to vertex i + 1.
  std::vector<std::vector<std::vector<std::size_t>>> part_loop_edges;
  std::vector<RidgeLoop> loops;

  std::size_t count(EdgeKind kind) const;
};

// The objects, edges and RE loops of `polygons` (with their `planes`, hsr::plane_of, and
// their `roles` under `light`, part_roles) for `light`.
RidgeEdgeLoops ridge_edge_loops(std::span<const hsr::Polygon3> polygons,
                                std::span<const hsr::Plane3> planes,
                                std::span<const PartRole> roles, const Light& light);

}  // namespace shadowgen::view::detail
