#include "merged_shapes.h"

#include "clipper/clip.h"
#include "clipper/merge.h"

namespace shadowgen::detail {

clipper::PolygonSet2 merged_shapes(std::span<const clipper::PolygonWithHoles2> pieces) {
  try {
    return clipper::merge_adjacent(pieces);
  } catch (const clipper::SnapRoundingError&) {
    return clipper::PolygonSet2(pieces.begin(), pieces.end());
  }
}

}  // namespace shadowgen::detail
