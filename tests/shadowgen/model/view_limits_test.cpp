// Tests of shadowgen/model/view_limits.h: what a view must be for its picture to show
// anything.

#include "shadowgen/model/view_limits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace shadowgen {
namespace {

// The narrowest field of view still gives a pixel of the tallest picture more than 64
// roundings of the eye-target distance (view_limits.h), and only just above √ε radians.
TEST(ViewLimits, TheNarrowestFieldOfViewLeavesAPixelAboveTheRounding) {
  const double epsilon = std::numeric_limits<double>::epsilon();
  const double fov_rad = kNarrowestFovDeg * std::numbers::pi / 180.0;
  EXPECT_GT(fov_rad, std::sqrt(epsilon));
  EXPECT_LT(fov_rad, 1.2 * std::sqrt(epsilon));
  const double pixel = 2.0 * std::tan(0.5 * fov_rad) / kLargestPictureSide;
  EXPECT_GT(pixel, 64.0 * epsilon);
  EXPECT_FALSE(within(1e-200, fov_range()));
  EXPECT_TRUE(within(kNarrowestFovDeg, fov_range()));
  EXPECT_FALSE(within(180.0, fov_range()));
}

TEST(ViewLimits, TheScaleRunsFromTheCoordinateRangeToTheSmallestExtent) {
  EXPECT_EQ(scale_range().low, 1e-100);
  EXPECT_EQ(scale_range().high, 1e100);
  EXPECT_FALSE(within(1e200, scale_range()));
  EXPECT_FALSE(within(1e-200, scale_range()));
  EXPECT_EQ(range_problem(1e200, scale_range()),
            "must lie between 1e-100 and 1e+100 pixels per unit");
}

// Along the sight: zero, or at a sine of √ε (1.49e-8) or less, either way; vectors of
// any length, scaled before they are multiplied.
TEST(ViewLimits, AnUpAlongTheSightIsOneWhoseRollIsItsOwnRounding) {
  const glm::dvec3 down(0.0, 0.0, -10.0);
  EXPECT_TRUE(along_sight(down, glm::dvec3(0.0)));
  EXPECT_TRUE(along_sight(down, glm::dvec3(0.0, 0.0, 1.0)));
  EXPECT_TRUE(along_sight(down, glm::dvec3(0.0, 0.0, -3.0)));
  EXPECT_TRUE(along_sight(down, glm::dvec3(1e-9, 0.0, 1.0)));
  EXPECT_FALSE(along_sight(down, glm::dvec3(1e-7, 0.0, 1.0)));
  EXPECT_FALSE(along_sight(down, glm::dvec3(1.0, 0.0, 0.0)));
  // Lengths of 1e-300 and 1e300 neither underflow nor overflow.
  EXPECT_FALSE(along_sight(glm::dvec3(0.0, 0.0, -1e-300), glm::dvec3(1e300, 0.0, 0.0)));
  EXPECT_TRUE(along_sight(glm::dvec3(0.0, 0.0, -1e-300), glm::dvec3(0.0, 0.0, 1e300)));

  EXPECT_EQ(up_problem(down, glm::dvec3(0.0), "from --eye to --target"), "must not be zero");
  EXPECT_EQ(up_problem(down, glm::dvec3(0.0, 0.0, 1.0), "from --eye to --target"),
            "must not be parallel to the direction from --eye to --target");
  EXPECT_EQ(up_problem(down, glm::dvec3(0.0, 1.0, 0.0), "from --eye to --target"), std::nullopt);
}

}  // namespace
}  // namespace shadowgen
