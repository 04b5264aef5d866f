#include "shadowgen/sky/energyplus_sky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>

#include "bench/scenes/street_canyon.h"
#include "tests/shadowgen/sky/sky_test_faces.h"

namespace shadowgen::sky {
namespace {

constexpr double kPi = std::numbers::pi;

using test::quad;

// A unit square through the origin whose front normal has tilt `tilt_deg` from the zenith
// and faces `azimuth_deg` clockwise from north.
Face tilted_square(double tilt_deg, double azimuth_deg) {
  const double b = tilt_deg * kPi / 180.0, a = azimuth_deg * kPi / 180.0;
  const glm::dvec3 across{std::cos(a), -std::sin(a), 0.0};  // horizontal, in the face
  const glm::dvec3 normal{std::sin(b) * std::sin(a), std::sin(b) * std::cos(a), std::cos(b)};
  const glm::dvec3 up_slope = glm::cross(normal, across);
  return quad("tilted", -0.5 * up_slope - 0.5 * across, -0.5 * up_slope + 0.5 * across,
              0.5 * up_slope + 0.5 * across, 0.5 * up_slope - 0.5 * across);
}

double iso_sky(const EnergyPlusSkyShading& s, std::size_t f) {
  return shading_ratio(s.with_iso_sky[f], s.without_iso_sky[f]);
}
double horizon(const EnergyPlusSkyShading& s, std::size_t f) {
  return shading_ratio(s.with_horizon[f], s.without_horizon[f]);
}

TEST(EnergyPlusSky, TheDirectionsAreEnergyPlusSixAltitudesByTwentyFourAzimuths) {
  const std::vector<SkyPatch> patches = energyplus_sky_patches();
  ASSERT_EQ(patches.size(), 144u);
  double solid_angle = 0.0;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 24; ++j) {
      const SkyPatch& p = patches[i * 24 + j];
      const double phi = (7.5 + 15.0 * i) * kPi / 180.0, theta = 15.0 * j * kPi / 180.0;
      EXPECT_NEAR(p.centre.x, std::cos(phi) * std::cos(theta), 1e-15);
      EXPECT_NEAR(p.centre.y, std::cos(phi) * std::sin(theta), 1e-15);
      EXPECT_NEAR(p.centre.z, std::sin(phi), 1e-15);
      solid_angle += p.solid_angle;
    }
  }
  EXPECT_NEAR(solid_angle, 2.0 * kPi, 1e-12);
  // EnergyPlus's weight: cos φ Δθ Δφ CTHETA, none from behind the face.
  const double step = 15.0 * kPi / 180.0;
  EXPECT_DOUBLE_EQ(energyplus_sky_weight(patches[0], {1.0, 0.0, 0.0}),
                   std::cos(7.5 * kPi / 180.0) * step * step * std::cos(7.5 * kPi / 180.0));
  EXPECT_EQ(energyplus_sky_weight(patches[12], {1.0, 0.0, 0.0}), 0.0);
}

TEST(EnergyPlusSky, AnUnobstructedFaceGetsOneExactly) {
  for (const double tilt : {0.0, 30.0, 45.0, 90.0, 135.0}) {
    for (const double azimuth : {0.0, 37.0, 90.0, 180.0, 250.0}) {
      Scene scene;
      scene.file = "open";
      scene.faces.push_back(tilted_square(tilt, azimuth));
      const EnergyPlusSkyShading s = energyplus_sky_shading(scene, {}, false);
      EXPECT_GT(s.without_iso_sky[0], 0.0);
      EXPECT_EQ(iso_sky(s, 0), 1.0) << "tilt " << tilt << " azimuth " << azimuth;
      EXPECT_EQ(horizon(s, 0), 1.0) << "tilt " << tilt << " azimuth " << azimuth;
      EXPECT_FALSE(s.fine.has_value());
    }
  }
}

TEST(EnergyPlusSky, AFaceSeeingNoDirectionGetsZeroAsEnergyPlusDivides) {
  Scene scene;
  scene.file = "down";
  scene.faces.push_back(tilted_square(180.0, 0.0));
  const EnergyPlusSkyShading s = energyplus_sky_shading(scene, {}, false);
  EXPECT_EQ(s.without_iso_sky[0], 0.0);
  EXPECT_EQ(iso_sky(s, 0), 0.0);
  EXPECT_EQ(horizon(s, 0), 0.0);
}

// A small floor face 0.5 south of a wall 10,000 high and long: every direction with a
// northward component (sin θ > 0, θ from east) is blocked, and the others (θ = 0°, 180°
// along the wall, and 195° to 345°) reach it, 13 of the 24 at every altitude; so both ratios
// are 13/24, whatever the altitudes' weights.
TEST(EnergyPlusSky, AFloorBesideATallWallGetsThirteenTwentyFourths) {
  Scene scene;
  scene.file = "wall";
  scene.faces.push_back(quad("floor", {-0.01, -0.01, 0.0}, {0.01, -0.01, 0.0}, {0.01, 0.01, 0.0},
                             {-0.01, 0.01, 0.0}));
  scene.faces.push_back(quad("wall", {-5000.0, 0.5, 0.0}, {5000.0, 0.5, 0.0},
                             {5000.0, 0.5, 10000.0}, {-5000.0, 0.5, 10000.0}));
  const EnergyPlusSkyShading s = energyplus_sky_shading(scene, {}, false);
  EXPECT_NEAR(iso_sky(s, 0), 13.0 / 24.0, 1e-14);
  EXPECT_NEAR(horizon(s, 0), 13.0 / 24.0, 1e-14);
}

// The middle of a street canyon's floor (H/W 1: walls 1 away either side, 2 high) sees a
// direction at altitude φ and azimuth θ when tan φ > 2 |sin θ|; the ratio is then
// Σ over those of cos φ sin φ / Σ over all of cos φ sin φ, which comes to 7/16, against
// the exact cos(atan 2) = 0.4472 that the fine subdivision gets close to.
TEST(EnergyPlusSky, AStreetCanyonFloorGetsTheHandComputedRatio) {
  double with = 0.0, without = 0.0, horizon_with = 0.0;
  for (int i = 0; i < 6; ++i) {
    const double phi = (7.5 + 15.0 * i) * kPi / 180.0;
    for (int j = 0; j < 24; ++j) {
      const double weight = std::cos(phi) * std::sin(phi);
      const bool lit = std::tan(phi) > 2.0 * std::fabs(std::sin(15.0 * j * kPi / 180.0));
      without += weight;
      with += lit ? weight : 0.0;
      horizon_with += (i == 0 && lit) ? 1.0 : 0.0;
    }
  }
  EXPECT_NEAR(with / without, 7.0 / 16.0, 1e-14);
  EXPECT_EQ(horizon_with, 2.0);  // θ = 0° and 180°, along the street

  SkyOptions options;
  options.subdivisions = 4;
  const EnergyPlusSkyShading s = energyplus_sky_shading(bench::street_canyon(1.0), options, true);
  EXPECT_NEAR(iso_sky(s, 0), 7.0 / 16.0, 1e-14);
  EXPECT_NEAR(horizon(s, 0), 2.0 / 24.0, 1e-14);
  ASSERT_TRUE(s.fine.has_value());
  const double exact = bench::street_canyon_sky_view_factor(1.0);
  EXPECT_NEAR(fine_shading_ratio(*s.fine, 0) / exact, 1.0, 0.01);
  EXPECT_EQ(s.fine->patches.size(), 144u * 16u + 1u);
}

TEST(EnergyPlusSky, TheFineColumnIsTheSkyExposuresRatio) {
  SkyOptions options;
  options.subdivisions = 2;
  const Scene scene = bench::street_canyon(0.5);
  const EnergyPlusSkyShading s = energyplus_sky_shading(scene, options, true);
  const SkyExposure alone = sky_exposure(scene, options);
  ASSERT_TRUE(s.fine.has_value());
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    EXPECT_EQ(fine_shading_ratio(*s.fine, f), fine_shading_ratio(alone, f));
  }
}

}  // namespace
}  // namespace shadowgen::sky
