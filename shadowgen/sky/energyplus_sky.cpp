#include "shadowgen/sky/energyplus_sky.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <numeric>

namespace shadowgen::sky {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kAltitudeStep = 0.5 * kPi / kEnergyPlusAltitudes;  // DPhi
constexpr double kAzimuthStep = 2.0 * kPi / kEnergyPlusAzimuths;    // DTheta
constexpr std::size_t kDirections = kEnergyPlusAltitudes * kEnergyPlusAzimuths;

}  // namespace

std::vector<SkyPatch> energyplus_sky_patches() {
  std::vector<SkyPatch> out;
  out.reserve(kDirections);
  for (int i = 0; i < kEnergyPlusAltitudes; ++i) {
    const double phi = 0.5 * kAltitudeStep + i * kAltitudeStep;  // PhiMin + IPhi DPhi
    for (int j = 0; j < kEnergyPlusAzimuths; ++j) {
      const double theta = j * kAzimuthStep;  // counterclockwise from east
      SkyPatch patch;
      patch.altitude_min = phi - 0.5 * kAltitudeStep;
      patch.altitude_max = phi + 0.5 * kAltitudeStep;
      const double azimuth = 0.5 * kPi - theta;  // clockwise from north
      patch.azimuth_min = azimuth - 0.5 * kAzimuthStep;
      patch.azimuth_max = azimuth + 0.5 * kAzimuthStep;
      patch.centre = {std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta),
                      std::sin(phi)};
      patch.solid_angle =
          kAzimuthStep * (std::sin(patch.altitude_max) - std::sin(patch.altitude_min));
      out.push_back(patch);
    }
  }
  return out;
}

double energyplus_sky_weight(const SkyPatch& patch, const glm::dvec3& normal) {
  const double cos_theta = glm::dot(patch.centre, normal);  // EnergyPlus's CTHETA
  if (cos_theta < 0.0) return 0.0;
  const double phi = 0.5 * (patch.altitude_min + patch.altitude_max);
  return std::cos(phi) * (kAzimuthStep * kAltitudeStep) * cos_theta;
}

std::vector<SkyPatch> energyplus_sky_lights(const SkyOptions& options, bool fine) {
  std::vector<SkyPatch> out = energyplus_sky_patches();
  if (fine) {
    const std::vector<SkyPatch> patches = reinhart_patches(options.subdivisions);
    out.insert(out.end(), patches.begin(), patches.end());
  }
  return out;
}

EnergyPlusSkyShading energyplus_sky_shading(const Scene& scene, const SkyOptions& options,
                                            bool fine) {
  const std::vector<SkyPatch> lights = energyplus_sky_lights(options, fine);
  const SunPathHours path = sky_lit_areas(scene, lights, options);
  const std::size_t faces = scene.faces.size();
  const double north_axis_deg = scene.site ? scene.site->north_axis_deg : 0.0;
  EnergyPlusSkyShading out;
  out.with_iso_sky.assign(faces, 0.0);
  out.without_iso_sky.assign(faces, 0.0);
  out.with_horizon.assign(faces, 0.0);
  out.without_horizon.assign(faces, 0.0);
  for (std::size_t f = 0; f < faces; ++f) {
    const std::vector<SkyPart> parts = sky_parts(scene.faces[f], north_axis_deg);
    double area = 0.0;
    for (const SkyPart& part : parts) area += part.area;
    if (area <= 0.0) continue;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const SkyPart& part = parts[i];
      if (!part.oriented) continue;
      for (std::size_t p = 0; p < kDirections; ++p) {
        const double weight = energyplus_sky_weight(lights[p], part.normal);
        if (weight <= 0.0) continue;
        const double lit = sky_lit_area(path, f, i, part, p, lights[p].centre);
        const double with = lit / area * weight;
        const double without = part.area / area * weight;
        out.with_iso_sky[f] += with;
        out.without_iso_sky[f] += without;
        if (p < static_cast<std::size_t>(kEnergyPlusAzimuths)) {
          out.with_horizon[f] += with;
          out.without_horizon[f] += without;
        }
      }
    }
  }
  if (fine) {
    out.fine = sky_exposure_of(scene, path, kDirections,
                               std::vector<SkyPatch>(lights.begin() + kDirections, lights.end()));
  }
  return out;
}

double shading_ratio(double with, double without) { return without > 0.0 ? with / without : 0.0; }

double fine_shading_ratio(const SkyExposure& exposure, std::size_t face) {
  const std::vector<double>& lit = exposure.lit_weight.at(face);
  const std::vector<double>& open = exposure.open_weight.at(face);
  return shading_ratio(std::accumulate(lit.begin(), lit.end(), 0.0),
                       std::accumulate(open.begin(), open.end(), 0.0));
}

}  // namespace shadowgen::sky
