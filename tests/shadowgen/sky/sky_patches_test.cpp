#include "shadowgen/sky/sky_patches.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

namespace shadowgen::sky {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SkyPatches, TregenzaHasItsPublishedRowsAndCap) {
  const std::vector<SkyPatch> patches = reinhart_patches(1);
  ASSERT_EQ(patches.size(), 145u);
  // Rows of 12°: 30, 30, 24, 24, 18, 12, 6 patches, then the cap above 84°.
  const int rows[] = {30, 30, 24, 24, 18, 12, 6};
  std::size_t i = 0;
  for (int r = 0; r < 7; ++r) {
    for (int c = 0; c < rows[r]; ++c, ++i) {
      EXPECT_NEAR(patches[i].altitude_min, r * 12.0 * kPi / 180.0, 1e-15);
      EXPECT_NEAR(patches[i].altitude_max, (r + 1) * 12.0 * kPi / 180.0, 1e-15);
      EXPECT_NEAR(patches[i].azimuth_max - patches[i].azimuth_min, 2.0 * kPi / rows[r], 1e-15);
    }
  }
  EXPECT_NEAR(patches.back().altitude_min, 84.0 * kPi / 180.0, 1e-15);
  // The first patch is centred on north at 6° altitude; the second lies east of it.
  EXPECT_NEAR(patches[0].centre.x, 0.0, 1e-15);
  EXPECT_NEAR(patches[0].centre.y, std::cos(6.0 * kPi / 180.0), 1e-15);
  EXPECT_NEAR(patches[0].centre.z, std::sin(6.0 * kPi / 180.0), 1e-15);
  EXPECT_GT(patches[1].centre.x, 0.0);
  EXPECT_EQ(patches.back().centre, glm::dvec3(0.0, 0.0, 1.0));
}

TEST(SkyPatches, ReinhartCountsAndHeights) {
  for (const int n : {1, 2, 4, 8}) {
    const std::vector<SkyPatch> patches = reinhart_patches(n);
    EXPECT_EQ(patches.size(), static_cast<std::size_t>(144 * n * n + 1)) << n;
    const double alpha = (kPi / 2.0) / (7 * n + 0.5);
    EXPECT_NEAR(patches.front().altitude_max, alpha, 1e-15);
    EXPECT_NEAR(patches.back().altitude_max - patches.back().altitude_min, alpha / 2.0, 1e-15);
  }
  EXPECT_EQ(reinhart_patches(2).size(), 577u);
  EXPECT_EQ(reinhart_patches(4).size(), 2305u);
}

TEST(SkyPatches, SolidAnglesSumToTheHemisphere) {
  for (const int n : {1, 2, 3, 4, 8}) {
    double sum = 0.0;
    for (const SkyPatch& p : reinhart_patches(n)) {
      sum += p.solid_angle;
      EXPECT_NEAR(glm::length(p.centre), 1.0, 1e-15);
    }
    EXPECT_NEAR(sum, 2.0 * kPi, 1e-12) << n;
  }
}

TEST(SkyPatches, SubdivisionsOutsideTheRangeAreRefused) {
  EXPECT_THROW(reinhart_patches(0), std::invalid_argument);
  EXPECT_THROW(reinhart_patches(kMostReinhartSubdivisions + 1), std::invalid_argument);
}

TEST(SkyPatches, SceneAxesTurnByTheNorthAxis) {
  // With the scene's +y 90° clockwise of north (+y points east), true north has the scene
  // azimuth -90°: it is the scene's -x.
  const glm::dvec3 north = scene_from_sky({0.0, 1.0, 0.0}, 90.0);
  EXPECT_NEAR(north.x, -1.0, 1e-15);
  EXPECT_NEAR(north.y, 0.0, 1e-15);
  const glm::dvec3 v{0.3, -0.4, 0.5};
  const glm::dvec3 back = sky_from_scene(scene_from_sky(v, 37.0), 37.0);
  EXPECT_NEAR(glm::length(back - v), 0.0, 1e-15);
}

}  // namespace
}  // namespace shadowgen::sky
