#include "shadowgen/view/png_writer.h"

#include <png.h>

#include <cstring>
#include <stdexcept>

#include "shadowgen/model/view_limits.h"
#include "shadowgen/output/atomic_file.h"

namespace shadowgen {

static_assert(kLargestPictureSide <= PNG_USER_WIDTH_MAX &&
                  kLargestPictureSide <= PNG_USER_HEIGHT_MAX,
              "libpng is built to write narrower pictures than kLargestPictureSide");

std::string png_bytes(const RgbImage& image) {
  if (image.width > kLargestPictureSide || image.height > kLargestPictureSide) {
    throw std::invalid_argument("png_bytes: the image is wider or taller than libpng writes");
  }
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() !=
          3 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height)) {
    throw std::invalid_argument("png_bytes: the image's size does not match its pixels");
  }
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  const png_int_32 stride = 3 * image.width;
  // First the size, then the bytes.
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), stride, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw std::runtime_error("libpng: " + message);
  }
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, image.rgb.data(), stride, nullptr)) {
    const std::string message = png.message;
    png_image_free(&png);
    throw std::runtime_error("libpng: " + message);
  }
  bytes.resize(size);
  return bytes;
}

void write_png(const RgbImage& image, const std::filesystem::path& path) {
  write_file_atomically(path, png_bytes(image));
}

}  // namespace shadowgen
