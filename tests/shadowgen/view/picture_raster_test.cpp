// A picture's pieces as pixels (shadowgen/view/picture_raster.h): each pixel the colour
// of the piece holding its centre, holes left out, shared edges giving each pixel to one
// piece, the background elsewhere.

#include "shadowgen/view/picture_raster.h"

#include <gtest/gtest.h>

#include <string>

namespace shadowgen {
namespace {

std::string hex(const RgbImage& image, int x, int y) {
  const std::uint8_t* p = image.at(x, y);
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", p[0], p[1], p[2]);
  return text;
}

TEST(PictureRaster, EachPixelTakesThePieceHoldingItsCentre) {
  Picture picture;
  picture.width = 8;
  picture.height = 4;
  picture.background = {1, 1, 1};
  Piece left;  // x in [0, 4): pixels 0..3, a hole over pixel (1, 1)
  left.colour = {1, 0, 0};
  left.shape.outer = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  left.shape.holes = {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}};
  Piece right = left;  // shares the edge x = 4; x in [4, 6.5): centres 4.5, 5.5
  right.colour = {0, 0, 1};
  right.shape.outer = {{4, 0}, {6.5, 0}, {6.5, 4}, {4, 4}};
  right.shape.holes.clear();
  picture.pieces = {left, right};
  const RgbImage image = rasterize_picture(picture);
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.height, 4);
  EXPECT_EQ(hex(image, 0, 0), "#ff0000");
  EXPECT_EQ(hex(image, 3, 3), "#ff0000");
  EXPECT_EQ(hex(image, 1, 1), "#ffffff");  // the hole
  EXPECT_EQ(hex(image, 4, 0), "#0000ff");
  EXPECT_EQ(hex(image, 5, 2), "#0000ff");
  EXPECT_EQ(hex(image, 6, 2), "#ffffff");  // centre 6.5: on the edge, outside the half-open span
  EXPECT_EQ(hex(image, 7, 3), "#ffffff");
}

}  // namespace
}  // namespace shadowgen
