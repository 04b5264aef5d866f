#pragma once

// The overlay's plane graph (overlay.h): a vertex for every distinct point of both
// operands' snapped loops, an edge for every distinct segment with each operand's net
// multiplicity along it, and each vertex's edges in counter-clockwise order around it.
// Built here; its windings are spread by overlay_windings.h and read by overlay.cpp.
//
// The small accessors below run in the inner loops of both later steps, in other
// translation units: they are inline here so that no call crosses one there.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "clipper/polygon.h"
#include "point_index.h"

namespace shadowgen::clipper::detail {

using Winding = std::array<int, 2>;  // the subject's, the clip's

inline Winding operator+(const Winding& a, const Winding& b) { return {a[0] + b[0], a[1] + b[1]}; }
inline Winding operator-(const Winding& a, const Winding& b) { return {a[0] - b[0], a[1] - b[1]}; }

// A segment of the graph, run from its lower id to its higher.
struct OverlayEdge {
  std::uint32_t lo, hi;
  Winding multiplicity{};  // net runs lo -> hi, per operand
  Winding right{};         // winding numbers of the faces on its right (once known)
  bool known = false;
};

// A segment's run, lo -> hi or back, in one operand's loops.
struct EdgeRun {
  std::uint32_t hi;
  int operand;
  int sign;  // +1 for lo -> hi
};

// The graph of one overlay, and its storage kept per thread from call to call: the graph
// is built anew for every clip, and a clip of small polygons (a few dozen points) would
// otherwise spend much of its time allocating it.
struct OverlayGraph {
  PointIndex index{0};
  std::vector<std::vector<std::uint32_t>> ids[2];  // per operand, loop: its points' ids
  std::vector<OverlayEdge> edges;
  std::vector<std::uint32_t> first;      // per vertex: its slice of incidence
  std::vector<std::uint32_t> incidence;  // edge indices, counter-clockwise around each vertex
  std::vector<std::uint32_t> part;       // per vertex: its connected part (where looked for)
  // Scratch of the steps that build those.
  std::vector<EdgeRun> runs;
  std::vector<std::uint32_t> run_first, fill, seeds, stack, todo;
  std::vector<char> done;

  // The edges at vertex v, counter-clockwise.
  std::span<std::uint32_t> edges_at(std::uint32_t v) {
    return {incidence.data() + first[v], first[v + 1] - first[v]};
  }
};

// The end of e that is not v.
inline std::uint32_t far_end(const OverlayEdge& e, std::uint32_t v) {
  return e.lo == v ? e.hi : e.lo;
}

// The multiplicities of e run away from v, and the windings on its left so run.
inline Winding outward_multiplicity(const OverlayEdge& e, std::uint32_t v) {
  return e.lo == v ? e.multiplicity : Winding{} - e.multiplicity;
}
inline Winding left_of_outward(const OverlayEdge& e, std::uint32_t v) {
  return e.lo == v ? e.right + e.multiplicity : e.right;
}

// Makes `graph` the graph of the loops (loops[0] the subject's, loops[1] the clip's):
// its ids, edges and incidence, reusing its storage. No edge's windings are known yet.
void build_overlay_graph(const std::vector<Loop2> (&loops)[2], OverlayGraph& graph);

}  // namespace shadowgen::clipper::detail
