#pragma once

// Regions of the image that hidden-surface removal settles independently, in parallel.
//
// What a point of the image shows depends only on the polygons that cover that point, so
// the image can be cut into rectangles and each settled on its own: a piece that crosses
// a region's side is clipped to each region it reaches, and the fragments of one polygon
// merge again across the sides afterwards (as the tiles of a wide polygon do). The layout
// depends on the pieces alone, never on how many threads run, so the result is the same
// byte for byte whatever the thread count.

#include <cstddef>
#include <span>
#include <vector>

#include "clipper/box.h"

namespace shadowgen::hsr {

// How many regions an image of `pieces` pieces is cut into: one below a few thousand
// pieces (a region's own bookkeeping and the clips along its sides would cost more than
// it saves), then one per that many, at most 256.
std::size_t region_count_for(std::size_t pieces);

// About `count` rectangles tiling the box around `boxes` (the pieces' bounding boxes):
// columns cut at quantiles of the boxes' centres along x, rows at quantiles along y, so
// that each region holds about as many pieces. Row by row from the lowest, left to right.
// Empty when `boxes` is; one region (the whole box) when count <= 1.
std::vector<clipper::Box2> image_regions(std::span<const clipper::Box2> boxes, std::size_t count);

}  // namespace shadowgen::hsr
