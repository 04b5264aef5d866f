#include "clipper/clip.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "clipper/detail/boundary_graph.h"
#include "clipper/detail/overlay.h"
#include "clipper/detail/snap_rounding.h"
#include "clipper/normalize.h"

namespace shadowgen::clipper {
namespace {

// One operand as the clipper sees it: every loop (outer and hole alike) oriented so the
// region lies on its left.
using Boundary = std::vector<Loop2>;

bool has_vertex(const Loop2& loop, const Point2& v) {
  return std::find(loop.begin(), loop.end(), v) != loop.end();
}

bool has_vertex(const PolygonWithHoles2& polygon, const Point2& v) {
  return has_vertex(polygon.outer, v) ||
         std::any_of(polygon.holes.begin(), polygon.holes.end(),
                     [&v](const Loop2& hole) { return has_vertex(hole, v); });
}

Boundary boundary_of(const PolygonSet2& polygons) {
  Boundary loops;
  for (const PolygonWithHoles2& p : polygons) {
    loops.push_back(p.outer);
    for (const Loop2& h : p.holes) loops.push_back(h);
  }
  return loops;
}

struct Box {
  double xmin, xmax, ymin, ymax;
};

Box bounds(const Boundary& loops) {
  Box b{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const Loop2& l : loops) {
    for (const Point2& p : l) {
      b.xmin = std::min(b.xmin, p.x);
      b.xmax = std::max(b.xmax, p.x);
      b.ymin = std::min(b.ymin, p.y);
      b.ymax = std::max(b.ymax, p.y);
    }
  }
  return b;
}

bool overlap(const Box& a, const Box& b) {
  return a.xmin <= b.xmax && b.xmin <= a.xmax && a.ymin <= b.ymax && b.ymin <= a.ymax;
}

// Snaps all the pieces together and remakes each from its snapped loops. A step of the
// clips in sequence may route its subject's boundary through a clip vertex within a
// pixel of it, where that boundary is also the boundary of inside pieces an earlier step
// made, which keep it as it was: pieces of different steps could then overlap by a
// hair. Snapped together, every boundary two pieces share runs through the same
// vertices, and each piece is the region its own snapped loops wind around.
void conform(ClipResult& result) {
  std::vector<Loop2> loops[2];
  std::vector<std::size_t> first;  // per piece, its first loop
  for (const PolygonSet2* set : {&result.inside, &result.outside}) {
    for (const PolygonWithHoles2& p : *set) {
      first.push_back(loops[0].size());
      loops[0].push_back(p.outer);
      for (const Loop2& h : p.holes) loops[0].push_back(h);
    }
  }
  first.push_back(loops[0].size());
  detail::snap_round(loops);
  const std::size_t inside_count = result.inside.size();
  ClipResult remade;
  for (std::size_t k = 0; k + 1 < first.size(); ++k) {
    std::vector<Loop2> piece[2];
    for (std::size_t l = first[k]; l < first[k + 1]; ++l) {
      if (!loops[0][l].empty()) piece[0].push_back(std::move(loops[0][l]));
    }
    PolygonSet2& into = k < inside_count ? remade.inside : remade.outside;
    for (PolygonWithHoles2& p : detail::assemble_polygons(detail::overlay(piece).outside)) {
      into.push_back(std::move(p));
    }
  }
  result = std::move(remade);
}

}  // namespace

ClipResult clip(const PolygonSet2& subject, const PolygonSet2& clip_region) {
  ClipResult result;
  PolygonSet2 a = normalized(subject);
  const PolygonSet2 b = normalized(clip_region);
  if (a.empty()) return result;
  Boundary loops[2] = {boundary_of(a), boundary_of(b)};
  if (b.empty() || !overlap(bounds(loops[0]), bounds(loops[1]))) {
    result.outside = std::move(a);
    return result;
  }
  // Snapped together, the two boundaries form a plane graph in doubles, and every
  // decision from here on is exact on it.
  detail::snap_round(loops);
  const detail::OverlayEdges edges = detail::overlay(loops);
  result.inside = detail::assemble_polygons(edges.inside);
  result.outside = detail::assemble_polygons(edges.outside);
  return result;
}

ClipResult clip(const PolygonWithHoles2& subject, const PolygonWithHoles2& clip_region) {
  return clip(PolygonSet2{subject}, PolygonSet2{clip_region});
}

ClipResult clip(const PolygonWithHoles2& subject, std::span<const PolygonWithHoles2> clips) {
  // The outside pieces left by one clip are the subject of the next, so the inside
  // pieces of different clips never overlap even where the clips do.
  // Re-clipping rounded pieces against clips that overlap earlier ones can leave slivers
  // that exist only because of that rounding; pieces within the rounding bound go, unless
  // every vertex of theirs was already a vertex of the step's operands: such a piece was
  // not made by rounding (a thin subject the clip does not touch comes back whole).
  auto drop_rounding_slivers = [](PolygonSet2& set, const PolygonSet2& before,
                                  const PolygonWithHoles2& c) {
    auto is_operand_vertex = [&](const Point2& v) {
      return has_vertex(c, v) || std::any_of(before.begin(), before.end(),
                                             [&v](const auto& p) { return has_vertex(p, v); });
    };
    std::erase_if(set, [&](const PolygonWithHoles2& p) {
      if (std::fabs(signed_area(p.outer)) > rounding_area_bound(p.outer)) return false;
      return !std::all_of(p.outer.begin(), p.outer.end(), is_operand_vertex);
    });
  };
  ClipResult result;
  result.outside = normalized(PolygonSet2{subject});
  // Once a step has made inside pieces, every later step snaps their former neighbour,
  // the subject's remains, again.
  bool snapped_after_cut = false;
  for (const PolygonWithHoles2& c : clips) {
    if (result.outside.empty()) break;
    snapped_after_cut = snapped_after_cut || !result.inside.empty();
    ClipResult step = clip(result.outside, PolygonSet2{c});
    drop_rounding_slivers(step.inside, result.outside, c);
    drop_rounding_slivers(step.outside, result.outside, c);
    for (PolygonWithHoles2& p : step.inside) result.inside.push_back(std::move(p));
    result.outside = std::move(step.outside);
  }
  if (snapped_after_cut) conform(result);
  return result;
}

PolygonSet2 intersection(const PolygonSet2& a, const PolygonSet2& b) { return clip(a, b).inside; }

PolygonSet2 difference(const PolygonSet2& a, const PolygonSet2& b) { return clip(a, b).outside; }

}  // namespace shadowgen::clipper
