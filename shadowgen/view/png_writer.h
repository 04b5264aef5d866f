#pragma once

// A picture as pixels (8-bit RGB) and as a PNG file (libpng): 8 bits per channel, colour
// type RGB, no alpha, no gamma chunk (the values are written as render.h's shading gives
// them, round(255·v)).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shadowgen {

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel, row by row from the top

  const std::uint8_t* at(int x, int y) const {
    return rgb.data() + 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(x));
  }
};

// The PNG file's bytes. Throws std::invalid_argument for an image whose size does not
// match its pixels or whose side is beyond kLargestPictureSide
// (shadowgen/model/view_limits.h), std::runtime_error where
// libpng fails.
std::string png_bytes(const RgbImage& image);

// Writes the PNG through a temporary file and a rename (shadowgen/output/atomic_file.h):
// never a partial file.
void write_png(const RgbImage& image, const std::filesystem::path& path);

}  // namespace shadowgen
