#include "hsr/image_regions.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/hsr/scenes.h"

namespace shadowgen::hsr {
namespace {

double area(const clipper::Box2& b) { return (b.xmax - b.xmin) * (b.ymax - b.ymin); }

TEST(ImageRegions, FewPiecesMakeOneRegion) {
  EXPECT_EQ(region_count_for(0), 1u);
  EXPECT_EQ(region_count_for(5000), 1u);
  EXPECT_EQ(region_count_for(100000), 24u);
  EXPECT_EQ(region_count_for(100000000), 256u);
  EXPECT_TRUE(image_regions({}, 4).empty());
  const std::vector<clipper::Box2> boxes = test::random_image_boxes(1, 10);
  const std::vector<clipper::Box2> one = image_regions(boxes, 1);
  ASSERT_EQ(one.size(), 1u);
  for (const clipper::Box2& b : boxes) EXPECT_TRUE(one[0].contains(b));
}

// The regions tile the pieces' box: no two overlap, their areas add up to the box's, and
// every piece's centre lies in one of them; quantile cuts give each about as many.
TEST(ImageRegions, RegionsTileTheImageWithBalancedCounts) {
  const std::vector<clipper::Box2> boxes = test::random_image_boxes(2, 20000);
  clipper::Box2 extent;
  for (const clipper::Box2& b : boxes) extent.add(b);
  for (std::size_t count : {2u, 6u, 16u, 25u}) {
    const std::vector<clipper::Box2> regions = image_regions(boxes, count);
    EXPECT_GE(regions.size(), count * 3 / 4) << count;
    EXPECT_LE(regions.size(), count) << count;
    double sum = 0.0;
    for (std::size_t i = 0; i < regions.size(); ++i) {
      EXPECT_TRUE(extent.contains(regions[i]));
      sum += area(regions[i]);
      for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(regions[i].overlaps(regions[j]));
    }
    EXPECT_NEAR(sum, area(extent), 1e-9 * area(extent)) << count;
    std::vector<std::size_t> held(regions.size(), 0);
    for (const clipper::Box2& b : boxes) {
      const clipper::Point2 centre{0.5 * b.xmin + 0.5 * b.xmax, 0.5 * b.ymin + 0.5 * b.ymax};
      std::size_t homes = 0;
      for (std::size_t r = 0; r < regions.size(); ++r) {
        if (regions[r].contains(centre)) {
          ++homes;
          ++held[r];
        }
      }
      EXPECT_GE(homes, 1u);
    }
    const double fair = static_cast<double>(boxes.size()) / static_cast<double>(regions.size());
    for (std::size_t h : held) {
      EXPECT_GT(static_cast<double>(h), 0.5 * fair) << count;
      EXPECT_LT(static_cast<double>(h), 2.0 * fair) << count;
    }
  }
}

}  // namespace
}  // namespace shadowgen::hsr
