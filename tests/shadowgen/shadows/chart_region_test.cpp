#include "shadowgen/shadows/detail/chart_region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "clipper/polygon.h"
#include "tests/support/cgal_oracle.h"
#include "tests/support/random_polygons.h"

namespace shadowgen::shadows::detail {
namespace {

using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

PolygonWithHoles2 square(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

// The part: the grid's square; its pieces: the unit cells and, to be clipped as well,
// pieces of several cells. Every region is a random grid polygon: cells wholly inside
// or outside it (sorted by their boxes or by where they lie), cells it only touches, cells it
// crosses. What split() gives inside must be the region's area within the part, exactly
// up to the rounding of crossings, and outside the rest; nothing lost, nothing twice.
TEST(ChartRegion, SplitsPiecesIntoTheRegionsInsideAndOutside) {
  const double n = test::kGridSize;
  const PolygonSet2 whole{square(0, 0, n, n)};
  std::mt19937_64 rng(5);
  for (int round = 0; round < 60; ++round) {
    const PolygonWithHoles2 region = test::random_grid_polygon(rng);
    const test::ExactAreas exact = test::exact_clip_areas(whole, {region});
    const ChartRegion chart_region(whole, {region});
    PolygonSet2 pieces;
    for (int y = 0; y < test::kGridSize; ++y) {
      for (int x = 0; x < test::kGridSize; x += (y % 3 == 0 ? 3 : 1)) {
        const double w = (y % 3 == 0) ? std::min(3.0, n - x) : 1.0;
        pieces.push_back(square(x, y, x + w, y + 1));
      }
    }
    PolygonSet2 inside, outside;
    chart_region.split(pieces, outside, inside);
    SCOPED_TRACE("round " + std::to_string(round));
    const double tolerance = 1e-12 * n * n;
    EXPECT_NEAR(test::exact_area_of_pieces(inside), exact.inside, tolerance);
    EXPECT_NEAR(test::exact_area_of_pieces(outside), exact.outside, tolerance);
    EXPECT_NEAR(test::exact_area(inside), exact.inside, tolerance);    // no overlap
    EXPECT_NEAR(test::exact_area(outside), exact.outside, tolerance);  // no overlap
  }
}

TEST(ChartRegion, ARegionThatIsTheWholePartTakesEveryPieceWithoutAClip) {
  const PolygonSet2 whole{square(0, 0, 4, 4)};
  const ChartRegion everything(whole, whole);
  const PolygonSet2 pieces{square(0, 0, 1, 4), square(1, 0, 4, 4)};
  PolygonSet2 inside, outside;
  everything.split(pieces, outside, inside);
  EXPECT_TRUE(outside.empty());
  ASSERT_EQ(inside.size(), 2u);  // as they were: not merged by a clip
  EXPECT_EQ(inside[0].outer, pieces[0].outer);
  EXPECT_EQ(inside[1].outer, pieces[1].outer);
}

}  // namespace
}  // namespace shadowgen::shadows::detail
