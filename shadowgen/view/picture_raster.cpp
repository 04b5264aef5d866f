#include "shadowgen/view/picture_raster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "detail/colour_hex.h"

namespace shadowgen {
namespace {

// The x where the edge a-b crosses the line y = yc, taken from the endpoint of lesser y
// so that a shared edge gives the same x from either piece.
double crossing_x(clipper::Point2 a, clipper::Point2 b, double yc) {
  if (b.y < a.y || (b.y == a.y && b.x < a.x)) std::swap(a, b);
  return a.x + (yc - a.y) / (b.y - a.y) * (b.x - a.x);
}

void add_crossings(const clipper::Loop2& loop, double yc, std::vector<double>& xs) {
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const clipper::Point2& a = loop[i];
    const clipper::Point2& b = loop[(i + 1) % loop.size()];
    if ((a.y <= yc) != (b.y <= yc)) xs.push_back(crossing_x(a, b, yc));
  }
}

void fill_piece(const Piece& piece, RgbImage& image) {
  const std::array<std::uint8_t, 3> rgb = view::detail::colour_bytes(piece.colour);
  double top = piece.shape.outer.front().y;
  double bottom = top;
  for (const clipper::Point2& p : piece.shape.outer) {
    top = std::min(top, p.y);
    bottom = std::max(bottom, p.y);
  }
  // Rows whose centre lies within [top, bottom].
  const int first = std::max(0, static_cast<int>(std::ceil(top - 0.5)));
  const int last = std::min(image.height - 1, static_cast<int>(std::floor(bottom - 0.5)));
  std::vector<double> xs;
  for (int y = first; y <= last; ++y) {
    const double yc = y + 0.5;
    xs.clear();
    add_crossings(piece.shape.outer, yc, xs);
    for (const clipper::Loop2& hole : piece.shape.holes) add_crossings(hole, yc, xs);
    std::sort(xs.begin(), xs.end());
    for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
      // Pixels whose centre x + 0.5 lies in [xs[i], xs[i + 1]).
      const int from = std::max(0, static_cast<int>(std::ceil(xs[i] - 0.5)));
      const int to = std::min(image.width, static_cast<int>(std::ceil(xs[i + 1] - 0.5)));
      for (int x = from; x < to; ++x) {
        std::uint8_t* pixel = image.rgb.data() + 3 * (static_cast<std::size_t>(y) * image.width +
                                                      static_cast<std::size_t>(x));
        std::copy(rgb.begin(), rgb.end(), pixel);
      }
    }
  }
}

}  // namespace

RgbImage rasterize_picture(const Picture& picture) {
  RgbImage image;
  image.width = picture.width;
  image.height = picture.height;
  const std::array<std::uint8_t, 3> background = view::detail::colour_bytes(picture.background);
  image.rgb.resize(3 * static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    std::copy(background.begin(), background.end(), image.rgb.begin() + i);
  }
  for (const Piece& piece : picture.pieces) {
    if (!piece.shape.outer.empty()) fill_piece(piece, image);
  }
  return image;
}

}  // namespace shadowgen
