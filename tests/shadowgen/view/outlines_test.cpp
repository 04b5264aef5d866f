// A picture's outlines (shadowgen/view/outlines.h) and its paths per colour
// (shadowgen/view/colour_paths.h): pieces of one face, or of one object of a model file,
// joined into one outline; pieces of one colour joined into one path, tile by tile,
// keeping their area.

#include "shadowgen/view/outlines.h"

#include <gtest/gtest.h>

#include "clipper/polygon.h"
#include "shadowgen/view/colour_paths.h"

namespace shadowgen {
namespace {

Piece square(std::size_t face, double x, double y, Rgb colour = {1, 0, 0}) {
  Piece piece;
  piece.face = face;
  piece.light_set = "sun";
  piece.colour = colour;
  piece.shape.outer = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
  return piece;
}

TEST(Outlines, OnePerFaceOrPerOriginObject) {
  Scene scene;
  scene.faces.resize(4);
  scene.faces[0].id = "yard";
  scene.faces[1].id = "b1/roof";
  scene.faces[1].origin = {"cityjson", "b1", "b1", "RoofSurface"};
  scene.faces[2].id = "b1/wall";
  scene.faces[2].origin = {"cityjson", "b1", "b1", "WallSurface"};
  scene.faces[3].id = "b2/roof";
  scene.faces[3].origin = {"cityjson", "b2", "b2", "RoofSurface"};
  // The yard in two pieces of two colours; b1's roof and wall side by side; b2 alone; a
  // layer's piece (by light) left out.
  std::vector<Piece> pieces = {square(0, 0, 0), square(0, 1, 0, {0, 0, 1}),
                               square(1, 5, 5), square(2, 6, 5),
                               square(3, 9, 9), square(0, 20, 20)};
  pieces.back().layer = 1;
  const std::vector<Outline> outlines = picture_outlines(scene, pieces);
  ASSERT_EQ(outlines.size(), 3u);
  EXPECT_EQ(outlines[0].face_id, "yard");
  EXPECT_EQ(outlines[0].object, "");
  EXPECT_EQ(outlines[1].face_id, "");
  EXPECT_EQ(outlines[1].object, "b1");
  EXPECT_EQ(outlines[2].object, "b2");
  // Each outline one polygon, the joined pieces' rectangle: 2 × 1, 2 × 1, 1 × 1.
  for (const Outline& outline : outlines) ASSERT_EQ(outline.shape.size(), 1u);
  EXPECT_EQ(outlines[0].shape[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(clipper::area(outlines[0].shape), 2.0);
  EXPECT_EQ(outlines[1].shape[0].outer.size(), 4u);
  EXPECT_DOUBLE_EQ(clipper::area(outlines[1].shape), 2.0);
  EXPECT_DOUBLE_EQ(clipper::area(outlines[2].shape), 1.0);
}

// Pieces of one colour join within a tile; across tiles they stay polygons of their own,
// in the one path; the area is the pieces' either way.
TEST(ColourPaths, PiecesOfOneColourJoinTileByTileAndKeepTheirArea) {
  Picture picture;
  picture.pieces = {square(0, 10, 10), square(1, 11, 10), square(0, 12, 10, {0, 0, 1}),
                    square(0, kMergeTile - 1, 10), square(1, kMergeTile, 10)};
  const std::vector<ColourPath> paths = colour_paths(picture);
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0].pieces, 4u);
  EXPECT_EQ(paths[0].light_set, "sun");
  // The two at x = 10, 11 joined; the two meeting at the tile's edge not.
  ASSERT_EQ(paths[0].shape.size(), 3u);
  EXPECT_DOUBLE_EQ(clipper::area(paths[0].shape), 4.0);
  EXPECT_EQ(paths[1].pieces, 1u);
  EXPECT_DOUBLE_EQ(clipper::area(paths[1].shape), 1.0);
}

}  // namespace
}  // namespace shadowgen
