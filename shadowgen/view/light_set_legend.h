#pragma once

// The legend of a lit picture (render.h): the light sets drawn, each in the colour that
// covers the most of the picture among its pieces (a set's shade varies from face to face
// with each face's angle to its lights), in the order of their lights (shadow, no light,
// first; svg_writer.h draws the list from the bottom up).
//
// A sun path's instants are lights, and their sets can run to hundreds: the legend keeps
// the kMaxLegendSets sets covering most of the picture, in that order, and says so in its
// caption ("the 12 of 64 largest"). A name longer than kMaxLegendLabel
// bytes is cut there, at a character's start, and ends in "…" (the full name is on the
// set's path, data-lights).

#include <cstddef>
#include <span>

#include "shadowgen/view/render.h"

namespace shadowgen {

inline constexpr std::size_t kMaxLegendSets = 12;
inline constexpr std::size_t kMaxLegendLabel = 26;

Legend light_set_legend(std::span<const Piece> pieces);

}  // namespace shadowgen
