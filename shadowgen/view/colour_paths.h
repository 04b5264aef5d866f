#pragma once

// A picture's pieces gathered into one shape per colour, so that a map of a district is a
// few paths, not one per piece (svg_writer.h draws them).
//
// Pieces go together where they are drawn alike and say the same: the same layer, the same
// colour (as written, "#rrggbb"), the same light set or hour band, the same side. Each
// group's pieces, which never overlap (render.h), are joined along the edges they share
// (clipper::merge_adjacent, in the picture's pixel coordinates), so the group covers the
// same points with fewer polygons and no inner edges; its area is the sum of its pieces'
// up to the snap rounding of the joined boundary. Groups come in the order of their first
// piece, so layers stay in order.
//
// The joining is done tile by tile, kMergeTile pixels square, each piece in the tile of its
// bounding box's least corner: the cost of joining grows faster than the pieces joined at
// once (a district's band holds hundreds of thousands), and tiles keep it in proportion
// to them. A group's polygons from neighbouring tiles meet along edges they share, drawn
// as one path all the same. Which faces a group holds is the outlines' to say
// (Picture::outlines), not the group's.

#include <cstddef>
#include <string>
#include <vector>

#include "clipper/polygon.h"
#include "shadowgen/view/render.h"

namespace shadowgen {

inline constexpr double kMergeTile = 64.0;

struct ColourPath {
  std::size_t layer = 0;
  Rgb colour;
  std::string light_set;  // the pieces' light set; empty in a sun-hours map
  bool banded =
      false;         // a sun-hours or radiation map's pieces (Piece::sun_hours or kwh_per_m2 set)
  std::string band;  // their band of hours or of kWh/m²
  bool back_side = false;
  clipper::PolygonSet2 shape;  // pixels
  std::size_t pieces = 0;      // how many pieces it joins
};

std::vector<ColourPath> colour_paths(const Picture& picture);

}  // namespace shadowgen
