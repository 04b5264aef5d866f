#include "shadowgen/sky/sky_patches.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace shadowgen::sky {
namespace {

constexpr std::array<int, 7> kTregenzaRowPatches{30, 30, 24, 24, 18, 12, 6};

glm::dvec3 direction_at(double altitude, double azimuth) {
  return {std::cos(altitude) * std::sin(azimuth), std::cos(altitude) * std::cos(azimuth),
          std::sin(altitude)};
}

}  // namespace

std::vector<SkyPatch> reinhart_patches(int subdivisions) {
  if (subdivisions < 1 || subdivisions > kMostReinhartSubdivisions) {
    throw std::invalid_argument("reinhart_patches: subdivisions must be 1 to " +
                                std::to_string(kMostReinhartSubdivisions));
  }
  const double pi = std::numbers::pi;
  const int rows = 7 * subdivisions;
  const double height = (pi / 2.0) / (rows + 0.5);
  std::vector<SkyPatch> patches;
  patches.reserve(static_cast<std::size_t>(144 * subdivisions * subdivisions + 1));
  for (int r = 0; r < rows; ++r) {
    const int count =
        subdivisions * kTregenzaRowPatches[static_cast<std::size_t>(r / subdivisions)];
    const double width = 2.0 * pi / count;
    const double a0 = r * height, a1 = (r + 1) * height;
    for (int c = 0; c < count; ++c) {
      SkyPatch patch;
      patch.altitude_min = a0;
      patch.altitude_max = a1;
      patch.azimuth_min = (c - 0.5) * width;
      patch.azimuth_max = (c + 0.5) * width;
      patch.centre = direction_at((r + 0.5) * height, c * width);
      patch.solid_angle = width * (std::sin(a1) - std::sin(a0));
      patches.push_back(patch);
    }
  }
  SkyPatch cap;
  cap.altitude_min = rows * height;
  cap.altitude_max = pi / 2.0;
  cap.azimuth_min = 0.0;
  cap.azimuth_max = 2.0 * pi;
  cap.centre = {0.0, 0.0, 1.0};
  cap.solid_angle = 2.0 * pi * (1.0 - std::sin(cap.altitude_min));
  patches.push_back(cap);
  return patches;
}

glm::dvec3 scene_from_sky(const glm::dvec3& v, double north_axis_deg) {
  // A true azimuth A is the scene azimuth A - north_axis_deg.
  const double t = north_axis_deg * std::numbers::pi / 180.0;
  const double c = std::cos(t), s = std::sin(t);
  return {v.x * c - v.y * s, v.x * s + v.y * c, v.z};
}

glm::dvec3 sky_from_scene(const glm::dvec3& v, double north_axis_deg) {
  const double t = north_axis_deg * std::numbers::pi / 180.0;
  const double c = std::cos(t), s = std::sin(t);
  return {v.x * c + v.y * s, -v.x * s + v.y * c, v.z};
}

}  // namespace shadowgen::sky
