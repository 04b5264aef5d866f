#include "merged_shapes.h"

#include <utility>
#include <vector>

#include "clipper/clip.h"
#include "clipper/merge.h"
#include "clipper/normalize.h"

namespace shadowgen::view::detail {

namespace {

// Without the vertices where the boundary runs straight on, where pieces met: exact
// (clipper::clean_loop), so the area stays what it is, and the path shorter.
clipper::PolygonSet2 without_straight_vertices(clipper::PolygonSet2 polygons) {
  clipper::PolygonSet2 out;
  for (clipper::PolygonWithHoles2& polygon : polygons) {
    if (!clipper::clean_loop(polygon.outer)) continue;
    std::erase_if(polygon.holes, [](clipper::Loop2& hole) { return !clipper::clean_loop(hole); });
    out.push_back(std::move(polygon));
  }
  return out;
}

}  // namespace

clipper::PolygonSet2 merged_shapes(std::span<const clipper::PolygonWithHoles2> pieces) {
  try {
    return without_straight_vertices(clipper::merge_adjacent(pieces));
  } catch (const clipper::SnapRoundingError&) {
    return clipper::PolygonSet2(pieces.begin(), pieces.end());
  }
}

}  // namespace shadowgen::view::detail
