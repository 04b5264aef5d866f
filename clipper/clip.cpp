#include "clipper/clip.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "clipper/box.h"
#include "clipper/normalize.h"
#include "detail/boundary_graph.h"
#include "detail/clip_prepared.h"
#include "detail/overlay.h"
#include "detail/snap_rounding.h"

namespace shadowgen::clipper {
namespace {

// One operand as the clipper sees it: every loop (outer and hole alike) oriented so the
// region lies on its left.
using Boundary = std::vector<Loop2>;

Boundary boundary_of(const PolygonSet2& polygons) {
  Boundary loops;
  for (const PolygonWithHoles2& p : polygons) {
    loops.push_back(p.outer);
    for (const Loop2& h : p.holes) loops.push_back(h);
  }
  return loops;
}

Box2 bounds(const Boundary& loops) {
  Box2 b;
  for (const Loop2& l : loops) {
    for (const Point2& p : l) b.add(p);
  }
  return b;
}

// Clips of more points than this give the loops kept per thread back when done.
constexpr std::size_t kKeptPoints = std::size_t{1} << 14;

// The clip of a normalized subject by a normalized region given as its loops and box.
ClipResult clip_normalized(PolygonSet2 a, const Boundary& clip_loops, const Box2& clip_box) {
  ClipResult result;
  if (a.empty()) return result;
  Box2 box;
  for (const PolygonWithHoles2& p : a) {
    box.add(box_of(p.outer));
    for (const Loop2& h : p.holes) box.add(box_of(h));
  }
  if (clip_loops.empty() || !box.touches_or_overlaps(clip_box)) {
    result.outside = std::move(a);
    return result;
  }
  // The subject's loops are its own from here on: moved, not copied. The clip's are
  // copied into loops kept per thread, whose storage the next clip reuses (a clip of
  // two small polygons spent a tenth of its allocations there).
  thread_local Boundary loops[2];
  loops[0].clear();
  for (PolygonWithHoles2& p : a) {
    loops[0].push_back(std::move(p.outer));
    for (Loop2& h : p.holes) loops[0].push_back(std::move(h));
  }
  loops[1] = clip_loops;
  // Snapped together, the two boundaries form a plane graph in doubles, and every
  // decision from here on is exact on it.
  detail::snap_round(loops);
  const detail::OverlayEdges edges = detail::overlay(loops);
  // A huge clip (a ground's lit region) gives its loops' storage back, as the overlay does.
  if (edges.point_count > kKeptPoints) loops[0] = loops[1] = Boundary{};
  result.inside = detail::assemble_polygons(edges.inside, edges.point_count);
  result.outside = detail::assemble_polygons(edges.outside, edges.point_count);
  return result;
}

ClipResult clip_normalized(PolygonSet2 a, const PolygonSet2& b) {
  const Boundary clip_loops = boundary_of(b);
  return clip_normalized(std::move(a), clip_loops, bounds(clip_loops));
}

}  // namespace

ClipResult detail::clip_prepared(PolygonSet2 subject, const PolygonSet2& clip_region) {
  return clip_normalized(std::move(subject), normalized(clip_region));
}

ClipResult clip(const PolygonSet2& subject, const PolygonSet2& clip_region) {
  return clip_normalized(normalized(subject), normalized(clip_region));
}

ClipResult clip(const PolygonWithHoles2& subject, const PolygonWithHoles2& clip_region) {
  return clip_normalized(normalized_polygon(subject), normalized_polygon(clip_region));
}

ClipResult clip(const PolygonWithHoles2& subject, std::span<const PolygonWithHoles2> clips) {
  // The clips together are one operand: where they overlap their winding numbers add up,
  // and a point lies in their union where the sum is positive (detail/overlay.h). One
  // snap rounding and one overlay then give every piece, all from the same snapped
  // graph, so pieces that share a boundary share its vertices. Clips whose boxes miss
  // the subject's cannot meet it and are left out.
  PolygonSet2 s = normalized_polygon(subject);
  if (s.empty()) return {};
  const Box2 box = box_of(s.front());  // one polygon in, at most one out
  PolygonSet2 near;
  for (const PolygonWithHoles2& c : clips) {
    if (box.touches_or_overlaps(box_of(c))) near.push_back(c);
  }
  return clip_normalized(std::move(s), normalized(near));
}

ClipRegion::ClipRegion(const PolygonWithHoles2& clip_region)
    : loops_(boundary_of(normalized_polygon(clip_region))), box_(bounds(loops_)) {}

ClipResult ClipRegion::clip(const PolygonWithHoles2& subject) const {
  return clip_normalized(normalized_polygon(subject), loops_, box_);
}

PolygonSet2 intersection(const PolygonSet2& a, const PolygonSet2& b) { return clip(a, b).inside; }

PolygonSet2 difference(const PolygonSet2& a, const PolygonSet2& b) { return clip(a, b).outside; }

}  // namespace shadowgen::clipper
