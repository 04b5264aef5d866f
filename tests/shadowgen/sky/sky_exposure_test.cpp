#include "shadowgen/sky/sky_exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "bench/scenes/street_canyon.h"
#include "shadowgen/sky/sky_lights.h"
#include "tests/shadowgen/sky/sky_test_faces.h"

namespace shadowgen::sky {
namespace {

constexpr double kPi = std::numbers::pi;

using test::quad;

// A unit square through the origin, tilted by `tilt_deg` about the x axis: its front
// normal (0, -sin β, cos β) faces south.
Face tilted_square(double tilt_deg) {
  const double b = tilt_deg * kPi / 180.0;
  const glm::dvec3 up_slope{0.0, std::cos(b), std::sin(b)};
  return quad("tilted", -up_slope * 0.5 + glm::dvec3(-0.5, 0, 0),
              -up_slope * 0.5 + glm::dvec3(0.5, 0, 0), up_slope * 0.5 + glm::dvec3(0.5, 0, 0),
              up_slope * 0.5 + glm::dvec3(-0.5, 0, 0));
}

SkyOptions options(int subdivisions) {
  SkyOptions o;
  o.subdivisions = subdivisions;
  return o;
}

TEST(SkyExposure, UnobstructedTiltedFaceGetsOnePlusCosOverTwo) {
  for (const int n : {1, kDefaultSubdivisions}) {
    for (const double tilt : {0.0, 30.0, 45.0, 90.0, 135.0}) {
      Scene scene;
      scene.file = "tilted";
      scene.faces.push_back(tilted_square(tilt));
      const SkyExposure exposure = sky_exposure(scene, options(n));
      const double expected = (1.0 + std::cos(tilt * kPi / 180.0)) / 2.0;
      EXPECT_NEAR(sky_view_factor(exposure, 0) / expected, 1.0, 0.002)
          << "MF:" << n << " tilt " << tilt;
      EXPECT_NEAR(exposure.ground_view_factor[0], 1.0 - expected, 1e-12);
    }
  }
}

TEST(SkyExposure, StreetCanyonFloorGetsCosAtanTwoHOverW) {
  for (const double height : {0.5, 1.0, 2.0}) {
    const SkyExposure exposure =
        sky_exposure(bench::street_canyon(height), options(kDefaultSubdivisions));
    const double expected = bench::street_canyon_sky_view_factor(height);
    EXPECT_NEAR(sky_view_factor(exposure, 0) / expected, 1.0, 0.005) << "H/W " << height;
    EXPECT_EQ(exposure.ground_view_factor[0], 0.0);
  }
}

TEST(SkyExposure, ShadingNeverAddsSky) {
  const SkyExposure exposure = sky_exposure(bench::street_canyon(1.0), options(1));
  for (std::size_t f = 0; f < 3; ++f) {
    for (std::size_t p = 0; p < exposure.patches.size(); ++p) {
      EXPECT_LE(exposure.lit_weight[f][p], exposure.open_weight[f][p] * (1.0 + 1e-12));
    }
  }
}

TEST(SkyLights, OneInstantOfTheSkyPathPerPatch) {
  Scene scene = bench::street_canyon(1.0);
  scene.site = Site{};
  scene.site->north_axis_deg = 90.0;
  const std::vector<SkyPatch> patches = reinhart_patches(1);
  const Scene sky = sky_scene(scene, patches);
  ASSERT_EQ(sky.lights.size(), 145u);
  EXPECT_EQ(sky.lights[0].id, "sky@1");
  ASSERT_TRUE(sky.lights[0].sun);
  EXPECT_EQ(sky.lights[0].sun->sun_id, "sky");
  EXPECT_TRUE(in_sun_path(sky.lights[0]));
  // Patch 1 is centred on true north, which is the scene's -x: its light travels +x, down.
  const glm::dvec3 d = sky.lights[0].direction;
  EXPECT_GT(d.x, 0.0);
  EXPECT_NEAR(d.y, 0.0, 1e-15);
  EXPECT_LT(d.z, 0.0);
  EXPECT_NEAR(sky.lights[0].sun->elevation_deg, 6.0, 1e-12);
}

}  // namespace
}  // namespace shadowgen::sky
