// Stratified samples over a face's parts: every part with area sampled, points inside
// their parts, weights that cover each part once, and the same points on every run.

#include "shadowgen/sampled/face_samples.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

namespace shadowgen::sampled {
namespace {

hsr::Polygon3 rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}}, {}};
}

// A 10 × 10 square with a 4 × 4 hole at [3,7]², a 0.01 × 0.01 sliver, and a part without
// area.
std::vector<PartTriangles> three_parts() {
  hsr::Polygon3 holed = rectangle(0, 0, 10, 10);
  holed.holes.push_back({{3, 3, 0}, {3, 7, 0}, {7, 7, 0}, {7, 3, 0}});
  return {part_triangles(holed), part_triangles(rectangle(20, 0, 20.01, 0.01)),
          part_triangles({{{0, 0, 1}, {1, 0, 1}, {2, 0, 1}}, {}})};
}

TEST(FaceSamples, EveryPartWithAreaGetsItsShare) {
  const std::vector<PartTriangles> parts = three_parts();
  const std::vector<int> n = samples_per_part(parts, 100);
  EXPECT_EQ(n, (std::vector<int>{99, 1, 0}));  // the sliver's share (0.0001) rounds to none
  EXPECT_EQ(samples_per_part(parts, 1), (std::vector<int>{1, 1, 0}));  // more than asked
  // Two parts of areas 3 and 1: one each, the other 98 shared 73.5 : 24.5, the tie of
  // remainders to the first.
  const std::vector<PartTriangles> two = {part_triangles(rectangle(0, 0, 3, 1)),
                                          part_triangles(rectangle(0, 1, 1, 2))};
  EXPECT_EQ(samples_per_part(two, 100), (std::vector<int>{75, 25}));
}

TEST(FaceSamples, PointsLieInTheirPartsAndWeightsCoverEachPartOnce) {
  const std::vector<PartTriangles> parts = three_parts();
  for (const int count : {7, 100, 1000}) {
    std::vector<FaceSample> samples;
    face_samples(parts, count, 3, samples);
    const std::vector<int> n = samples_per_part(parts, count);
    ASSERT_EQ(samples.size(), static_cast<std::size_t>(std::accumulate(n.begin(), n.end(), 0)));
    std::vector<double> weight(parts.size(), 0.0);
    for (const FaceSample& s : samples) {
      weight[s.part] += s.weight;
      EXPECT_EQ(s.point.z, 0.0);
      if (s.part == 0) {
        EXPECT_TRUE(s.point.x >= 0 && s.point.x <= 10 && s.point.y >= 0 && s.point.y <= 10);
        EXPECT_FALSE(s.point.x > 3 && s.point.x < 7 && s.point.y > 3 && s.point.y < 7)
            << "a point in the hole";
      } else {
        EXPECT_EQ(s.part, 1u);
        EXPECT_TRUE(s.point.x >= 20 && s.point.x <= 20.01 && s.point.y >= 0 && s.point.y <= 0.01);
      }
    }
    EXPECT_NEAR(weight[0], 1.0, 1e-12);
    EXPECT_NEAR(weight[1], 1.0, 1e-12);
    EXPECT_EQ(weight[2], 0.0);
  }
}

TEST(FaceSamples, StratifiedOverTheArea) {
  // 10 000 points on the holed square: each of its 84 unit cells (those not in the hole)
  // holds its share, 10 000 / 84 ≈ 119, within a few strata, far tighter than the ±33
  // (3 sigma) of independent points.
  const std::vector<PartTriangles> parts = {three_parts()[0]};
  std::vector<FaceSample> samples;
  face_samples(parts, 10000, 0, samples);
  std::vector<int> cell(100, 0);
  for (const FaceSample& s : samples) {
    ++cell[static_cast<int>(s.point.y) * 10 + static_cast<int>(s.point.x)];
  }
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x) {
      if (x >= 3 && x < 7 && y >= 3 && y < 7) continue;
      EXPECT_NEAR(cell[y * 10 + x], 10000.0 / 84.0, 12.0) << x << "," << y;
    }
  }
}

TEST(FaceSamples, SameFaceSamePointsOtherFaceOtherPoints) {
  const std::vector<PartTriangles> parts = three_parts();
  std::vector<FaceSample> a, b, c;
  face_samples(parts, 64, 5, a);
  face_samples(parts, 64, 5, b);
  face_samples(parts, 64, 6, c);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].point, b[i].point);
  EXPECT_NE(a[0].point, c[0].point);
}

TEST(FaceSamples, EstimateScalesByPartAreaAndIsExactWhenUniform) {
  const std::vector<PartTriangles> parts = three_parts();
  std::vector<FaceSample> samples;
  face_samples(parts, 100, 0, samples);
  std::vector<double> lit(samples.size(), 1.0);
  std::vector<double> areas = part_lit_areas(parts, samples, lit);
  EXPECT_EQ(areas[0], parts[0].area);  // exactly, however the weights round
  EXPECT_EQ(areas[1], parts[1].area);
  EXPECT_EQ(areas[2], 0.0);
  // The points with x < 5 lit: the estimate is the area times their weight.
  double weight = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    lit[i] = samples[i].part == 0 && samples[i].point.x < 5.0 ? 1.0 : 0.0;
    weight += lit[i] * samples[i].weight;
  }
  areas = part_lit_areas(parts, samples, lit);
  EXPECT_NEAR(areas[0], 84.0 * weight, 1e-12);
  EXPECT_NEAR(areas[0], 42.0, 3.0);  // half the holed square, to the strata crossed by x = 5
  EXPECT_EQ(areas[1], 0.0);
}

}  // namespace
}  // namespace shadowgen::sampled
