#pragma once

// The Weiler–Atherton clipper (Weiler and Atherton 1977; Atherton, Weiler and Greenberg
// 1978, section III): a concave subject with holes against a concave clip with holes,
// giving both the inside pieces (subject ∩ clip) and the outside pieces (subject − clip).
//
// Method. Every crossing and touching point of the two boundaries is inserted into both
// boundaries. Each stretch of a boundary between two such points lies wholly inside,
// wholly outside, or along the other region; an exact local test at the stretch's first
// point decides which (at a proper crossing this is the entry/exit alternation of the
// paper; at a mere touch it correctly does not alternate). The pieces are then traced:
// the subject's stretches inside the clip, switching at intersection points onto the
// clip's stretches inside the subject (reversed, for the outside pieces). Where several
// traced stretches meet at one point, the walk keeps to the tightest turn, and the loops
// are split at repeated vertices, so every output loop is simple.
//
// Input. Any PolygonWithHoles2 / PolygonSet2 whose region is well formed: loops simple,
// holes inside their outer loop, loops meeting at most at points. Orientation is free
// (normalized on entry). Repeated vertices, zero-area spikes and collinear vertices are
// removed first; loops left with no area are dropped.
//
// Near-degenerate input. Where rounded crossings fall on an input vertex, the side of a
// stretch is judged by the input edges that made its node; where several crossings less
// than a rounding apart merge into one node (a boundary cutting the thin tip of a spike),
// by exact point location of the stretch's first edge. A clockwise loop that rounding
// leaves outside every outer loop is a sliver within the rounding bound and is dropped.
// Self-crossing loops are outside the contract (the result is then unspecified, but the call
// returns).
//
// Output. Polygons in the conventions of clipper/polygon.h: outer loops counter-
// clockwise, holes clockwise and attached to the smallest outer loop that contains
// them, no repeated vertices, no zero-length edges, no spikes. Vertices where a loop runs
// straight on are kept: one may be where another loop touches it.
//
// Touching loops of one operand (a hole touching its outer loop, polygons of a set
// meeting at a point) are found first and the touching point made a vertex of both. At a
// point where several loops of the other operand meet, a stretch is inside where the
// winding number is 1.
//
// Exactness and tolerance. Every decision (do two edges cross, does a point lie on an
// edge, which side is a stretch on) is an exact predicate on the input doubles. Only new
// intersection points are rounded: each lies within
//     4u·min(|a1 − a0|, |b1 − b0|) + u·|P|,   u = 2^-53,
// of the exact crossing P of edges a and b (the parameter is formed from two exact
// orientation determinants, so the bound does not depend on the crossing angle).
// Vertices of the inputs are passed through unchanged. Consequently the areas of the
// pieces differ from the exact ones by at most the sum, over the constructed vertices,
// of that displacement times the length of the adjacent edges.
//
// Rounding repaired before tracing (detail/edge_noding.h). A rounded crossing can land
// across a nearby edge or past a vertex; the traced stretches are then noded again where
// they cross, until none do. And a vertex brought in from an earlier clip, a crossing
// rounded a hair off the edge it was made on, is taken as lying on any edge within twice
// the bound above (8u·|edge| + 2u·|P|), so the boundary does not fold back along that edge
// into a sliver. A crossing constructed within 2u·|P| of another vertex (where exact
// arithmetic puts it on that vertex) is merged into it, so the boundary does not run out
// and back through two points an ulp apart, and two crossings nearer each other than the
// sum of their own error bounds become one (detail/vertex_merge.h). All of these move the
// boundary by at most those bounds; the tolerances are those derived distances, nothing
// else.
//
// Limit. The placement error of a crossing grows with the length of its edges (4u·L).
// Where the other operand has features thinner than that along a long edge (a needle
// 1e8 long crossed within 1e-8 of its other edge), rounded crossings can land out of
// order and the pieces come out wrong; the fuzzer finds such inputs on raw doubles
// (README, Limits). Snap rounding of the crossings would lift it.
//
// Cost. Candidate edge pairs come from a sweep over x with y-interval rejection, so a
// clip costs O((n + k) log n + m) for n edges, k intersections and m pairs of edges
// whose x-ranges overlap, instead of the all-pairs O(n²).

#include <span>

#include "clipper/polygon.h"

namespace shadowgen::clipper {

struct ClipResult {
  PolygonSet2 inside;   // subject ∩ clip
  PolygonSet2 outside;  // subject − clip
};

ClipResult clip(const PolygonSet2& subject, const PolygonSet2& clip_region);
ClipResult clip(const PolygonWithHoles2& subject, const PolygonWithHoles2& clip_region);

// One subject against several clip polygons, as hidden-surface removal needs: inside is
// subject ∩ (union of the clips), outside is subject − (union of the clips). The clips
// may overlap each other. The outside pieces of one clip are clipped by the next; pieces
// whose area is within the rounding bound of their vertices and that have a vertex the
// step constructed (slivers that only rounding made) are dropped along the way.
ClipResult clip(const PolygonWithHoles2& subject, std::span<const PolygonWithHoles2> clips);

PolygonSet2 intersection(const PolygonSet2& a, const PolygonSet2& b);
PolygonSet2 difference(const PolygonSet2& a, const PolygonSet2& b);

}  // namespace shadowgen::clipper
