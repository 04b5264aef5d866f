#pragma once

// A Picture (shadowgen/render.h) as an SVG 1.1 document.
//
//   <?xml version="1.0" encoding="UTF-8"?>
//   <svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="W" height="H"
//        viewBox="0 0 W H" data-pixels-per-unit="S">       the last for orthographic views
//   <rect x="0" y="0" width="W" height="H" fill="#rrggbb"/>  the background
//   <path d="M x,y l dx,dy h dx v dy ... z m ... z" fill="#rrggbb" stroke="#rrggbb"
//   stroke-width="1.5"
//         stroke-linejoin="round" fill-rule="evenodd" data-lights="sun+lamp"/>
//                                       one per colour (colour_paths.h), in picture order,
//                                       its pieces joined where they touch, stroked in its
//                                       own colour so that no seam shows where colours meet
//   <g fill="none" stroke="#262626" stroke-width="0.75" stroke-linejoin="round"
//      data-outlines="">
//   <path d="..." data-face="wall"/>    each face's outline, or data-object="b1" for an
//   </g>                                 object of a model file (outlines.h)
//   <g data-north-arrow="330">...</g>    true north, clockwise from up (map_marks.h)
//   <g data-scale-bar="10" data-pixels="129.5">...</g>   orthographic views
//   (the legend)
//   </svg>
//
// With SvgOptions::pieces, one path per piece instead, unstroked, as
//   <path d="..." fill="#rrggbb" fill-rule="evenodd" data-face="wall" data-lights="sun"/>
// A sun-hours map's paths carry data-band="2–4 h" (with pieces: data-hours="1.5", their
// region's hours) instead of data-lights. The legend (Picture::legend: a sun-hours map's
// bands, a lit picture's light sets) is drawn in a strip 220 pixels wide to the right of
// the picture, which widens the document by that much (and makes it taller where the
// legend needs it); the background fills both:
//
//   <g font-family="sans-serif" font-size="12" fill="#000000" data-legend="sun-hours">
//   <text x=".." y="..">Sun hours: march21</text>              each caption line
//   <rect x=".." y=".." width="28" height="16" fill="#rrggbb" stroke="#000000"
//         stroke-width="0.5"/>                                 each entry, the last on top,
//   <text x=".." y="..">≥ 10 h</text>                            then its label
//   </g>
//
// Layers by light (render.h, render_by_light): the base's paths as above
// (data-lights="shadow"), then each light's layer in a group whose paths (unstroked) a
// viewer adds to what lies beneath them, which gives the lit picture's sum of lights:
//
//   <g style="mix-blend-mode:plus-lighter" data-light="sun">
//   <path d="..." fill="#rrggbb" fill-rule="evenodd" data-face="wall" data-lights="sun"/>
//   </g>
//
// (Browsers blend so; a viewer that does not, Inkscape for one, shows each layer's own
// colours over the base: hide the layers but one to see what that light reaches.)
//
// A path holds its polygons' outer loops and holes as closed subpaths; even-odd filling
// makes the holes. Coordinates are pixels, y down. The paths per colour and the outlines
// have them on a grid of 1/1000 pixel, relative and with no more digits than they need
// (detail/path_data.h: a map of a district in a few megabytes, each vertex within 0.0005
// pixel of the picture's in x and in y, and the shape's area within the bound it states);
// with SvgOptions::full_precision, and always in one path per piece, in the shortest form
// that reads back to the same double (std::to_chars), so the picture is exact at any zoom. A piece
// seen from its face's back side also carries data-side="back". Attribute values are
// XML-escaped; bytes that are not valid UTF-8 or not allowed in XML become U+FFFD.

#include <filesystem>
#include <string>

#include "shadowgen/view/render.h"

namespace shadowgen {

struct SvgOptions {
  // One path per piece, with its face (data-face) and its light set or hours, instead of
  // one path per colour.
  bool pieces = false;
  // The paths per colour and the outlines with every coordinate as the double it is, not
  // on the grid of 1/1000 pixel.
  bool full_precision = false;
};

std::string svg_document(const Picture& picture, const SvgOptions& options = {});

// Writes through a temporary file and a rename (shadowgen/atomic_file.h): never a
// partial file.
void write_svg(const Picture& picture, const std::filesystem::path& path,
               const SvgOptions& options = {});

}  // namespace shadowgen
