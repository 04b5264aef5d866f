#include "colour_hex.h"

#include <cmath>
#include <string_view>

namespace shadowgen::view::detail {

std::array<std::uint8_t, 3> colour_bytes(const Rgb& colour) {
  std::array<std::uint8_t, 3> bytes{};
  std::size_t i = 0;
  for (const double v : {colour.r, colour.g, colour.b}) {
    const double clamped = std::isfinite(v) ? std::fmin(std::fmax(v, 0.0), 1.0) : 0.0;
    bytes[i++] = static_cast<std::uint8_t>(std::lround(255.0 * clamped));
  }
  return bytes;
}

void append_colour(std::string& out, const Rgb& colour) {
  constexpr std::string_view kHex = "0123456789abcdef";
  out += '#';
  for (const std::uint8_t byte : colour_bytes(colour)) {
    out += kHex[byte >> 4];
    out += kHex[byte & 15];
  }
}

}  // namespace shadowgen::view::detail
