#pragma once

// A colour as SVG writes it, "#rrggbb": each channel clamped to [0, 1] (non-finite: 0) and
// written as the byte round(255·v). The PNG pictures use the same bytes.

#include <array>
#include <cstdint>
#include <string>

#include "shadowgen/view/render.h"

namespace shadowgen::view::detail {

std::array<std::uint8_t, 3> colour_bytes(const Rgb& colour);
void append_colour(std::string& out, const Rgb& colour);

}  // namespace shadowgen::view::detail
