#pragma once

// A picture (render.h) as pixels: each pixel takes the colour of the piece that holds its
// centre (x + 0.5, y + 0.5), the last such piece in the picture's order, or the
// background. Pieces are filled with the even-odd rule, as the SVG fills them, a centre
// on a piece's boundary counted on the side of increasing x (half-open spans), so pieces
// that share an edge never both take, nor both leave, a pixel whose centre lies on it.
// Colours are written as the SVG writes them (round(255·v) per channel), so a pixel
// inside a piece has that piece's "#rrggbb" exactly. The fills alone: the legend,
// outlines and marks of the SVG picture are not drawn.
//
// This is how `render --sun-hours --png` draws a sun-hours map: the same pieces as the
// SVG, sampled at the pixel centres.

#include "shadowgen/view/png_writer.h"
#include "shadowgen/view/render.h"

namespace shadowgen {

RgbImage rasterize_picture(const Picture& picture);

}  // namespace shadowgen
