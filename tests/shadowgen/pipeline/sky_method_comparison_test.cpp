// Sky view factors compared by method (shadowgen/pipeline/sky_method_comparison.h): the
// exact trial is sky_exposure's, a sampled trial's error is the difference of the two, and
// the rays' estimate converges as the sample points grow.

#include "shadowgen/pipeline/sky_method_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "shadowgen/sky/sky_exposure.h"
#include "tests/shadowgen/sky/sky_test_faces.h"

namespace shadowgen {
namespace {

using test::quad;

// A street 1 wide between walls 1 high facing into it, 200 long, its floor 20 long a face
// of its own: shadow edges of the walls cross the floor and the walls' lower parts, where
// sampled points miss part of the lit area.
Scene street() {
  Scene scene;
  scene.file = "street";
  scene.faces.push_back(quad("floor", {-10, -0.5, 0}, {10, -0.5, 0}, {10, 0.5, 0}, {-10, 0.5, 0}));
  scene.faces.push_back(
      quad("south", {100, -0.5, 0}, {-100, -0.5, 0}, {-100, -0.5, 1}, {100, -0.5, 1}));
  scene.faces.push_back(
      quad("north", {-100, 0.5, 0}, {100, 0.5, 0}, {100, 0.5, 1}, {-100, 0.5, 1}));
  return scene;
}

TEST(SkyMethodComparison, TheExactTrialIsTheSkyExposures) {
  const Scene canyon = street();
  const std::vector<Method> methods{Method{MethodKind::kRays, 16}};
  const sky::SkyComparison comparison = compare_sky_methods(canyon, 2, methods, {});
  ASSERT_EQ(comparison.trials.size(), 2u);
  EXPECT_TRUE(comparison.trials[0].method.exact());
  EXPECT_EQ(comparison.trials[1].method, methods[0]);
  sky::SkyOptions options;
  options.subdivisions = 2;
  const sky::SkyExposure exposure = sky::sky_exposure(canyon, options);
  for (std::size_t f = 0; f < canyon.faces.size(); ++f) {
    EXPECT_EQ(comparison.trials[0].sky_view_factor[f], sky::sky_view_factor(exposure, f));
    EXPECT_EQ(comparison.area[f], exposure.area[f]);
  }
  const sky::SkyErrors exact = sky::sky_errors(comparison, 0);
  EXPECT_EQ(exact.max_error, 0.0);
  EXPECT_EQ(exact.mean_error, 0.0);
  // The errors are those of the two columns.
  const sky::SkyErrors rays = sky::sky_errors(comparison, 1);
  double largest = 0.0, sum = 0.0, relative = 0.0;
  for (std::size_t f = 0; f < canyon.faces.size(); ++f) {
    const double e = comparison.trials[0].sky_view_factor[f];
    const double error = std::fabs(comparison.trials[1].sky_view_factor[f] - e);
    largest = std::max(largest, error);
    sum += error;
    relative = std::max(relative, error / e);
  }
  EXPECT_EQ(rays.max_error, largest);
  EXPECT_DOUBLE_EQ(rays.mean_error, sum / static_cast<double>(canyon.faces.size()));
  EXPECT_EQ(rays.max_relative_error, relative);
  EXPECT_GT(rays.max_error, 0.0);
}

TEST(SkyMethodComparison, RaysConvergeAsTheirPointsGrow) {
  const Scene canyon = street();
  const std::vector<Method> methods{Method{MethodKind::kRays, 4}, Method{MethodKind::kRays, 64},
                                    Method{MethodKind::kRays, 1024}};
  const sky::SkyComparison comparison = compare_sky_methods(canyon, 1, methods, {});
  ASSERT_EQ(comparison.trials.size(), 4u);
  const double coarse = sky::sky_errors(comparison, 1).mean_error;
  const double middle = sky::sky_errors(comparison, 2).mean_error;
  const double fine = sky::sky_errors(comparison, 3).mean_error;
  EXPECT_GT(coarse, middle);
  EXPECT_GT(middle, fine);
  EXPECT_LT(fine, 0.01);
}

}  // namespace
}  // namespace shadowgen
