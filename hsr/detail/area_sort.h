#pragma once

// One image region's area sort (Atherton, Weiler and Greenberg's hidden-surface removal
// by polygon area sort, run within a region of the picture): the pieces of the region,
// nearest first, each clipped against the one in front, what is seen of each returned as
// fragments of its parent polygon. Used by remove_hidden_surfaces (hidden_surface.h),
// which cuts the picture into regions and runs one sort per region in parallel.

#include <cstddef>
#include <utility>
#include <vector>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "hsr/hidden_surface.h"

namespace shadowgen::hsr::detail {

// A part of input polygon `parent`'s image.
struct Piece {
  clipper::PolygonWithHoles2 shape;
  std::size_t parent = 0;
};

// The fragments seen of `pieces`, appended to `out`; `nearness` and `facing` per input
// polygon (a piece's parent), as remove_hidden_surfaces has them; the clips and depth
// decisions counted in `stats`. Throws PolygonClipError naming the polygon whose clip
// failed.
void area_sort(std::vector<Piece> pieces, const std::vector<Nearness>& nearness,
               const std::vector<char>& facing, HsrStats& stats, std::vector<Fragment>& out);

// Runs a clip that works on input polygon `parent`; a clip that fails is passed on naming
// that polygon (PolygonClipError).
template <class Clip>
auto clip_of(std::size_t parent, Clip&& clip) {
  return clipper::failing_as<PolygonClipError>(parent, std::forward<Clip>(clip));
}

// The part of `piece` within rectangle `r` (a tile of a wide polygon, an image region).
// One clip, for the caller to count.
clipper::PolygonSet2 within_rectangle(const Piece& piece, const clipper::Box2& r);

}  // namespace shadowgen::hsr::detail
