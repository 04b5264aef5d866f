#include "shadowgen/sky/perez_sky.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "shadowgen/sky/patch_cosine.h"

namespace shadowgen::sky {
namespace {

constexpr double kPi = std::numbers::pi;

// Perez, Seals and Michalsky 1993, table 1: per clearness bin, a1..a4, b1..b4, c1..c4,
// d1..d4, e1..e4 (each x = x1 + x2 Z + Δ (x3 + x4 Z), but c and d in bin 0).
constexpr std::array<std::array<double, 20>, 8> kCoefficients{{
    {1.3525, -0.2576, -0.2690, -1.4366, -0.7670, 0.0007, 1.2734, -0.1233, 2.8000,  0.6004,
     1.2375, 1.0000,  1.8734,  0.6297,  0.9738,  0.2809, 0.0356, -0.1246, -0.5718, 0.9938},
    {-1.2219, -0.7730, 1.4148,  1.1016,  -0.2054, 0.0367, -3.9128, 0.9156, 6.9750,  0.1774,
     6.4477,  -0.1239, -1.5798, -0.5081, -1.7812, 0.1080, 0.2624,  0.0672, -0.2190, -0.4285},
    {-1.1000,  -0.2515, 0.8952,  0.0156, 0.2782, -0.1812, -4.5000, 1.1766, 24.7219, -13.0812,
     -37.7000, 34.8438, -5.0000, 1.5218, 3.9229, -2.6204, -0.0156, 0.1597, 0.4199,  -0.5562},
    {-0.5484,  -0.6654, -0.2672, 0.7117, 0.7234, -0.6219, -5.6812, 2.6297,  33.3389, -18.3000,
     -62.2500, 52.0781, -3.5000, 0.0016, 1.1477, 0.1062,  0.4659,  -0.3296, -0.0876, -0.0329},
    {-0.6000,  -0.3566, -2.5000, 2.3250,  0.2937, 0.0496, -5.6812, 1.8415, 21.0000, -4.7656,
     -21.5906, 7.2492,  -3.5000, -0.1554, 1.4062, 0.3988, 0.0032,  0.0766, -0.0656, -0.1294},
    {-1.0156, -0.3670, 1.0078,  1.4051,  0.2875,  -0.5328, -3.8500, 3.3750, 14.0000, -0.9999,
     -7.1406, 7.5469,  -3.4000, -0.1078, -1.0750, 1.5702,  -0.0672, 0.4016, 0.3017,  -0.4844},
    {-1.0000, 0.0211,  0.5025,  -0.5119, -0.3000, 0.1922, 0.7023, -1.6317, 19.0000, -5.0000,
     1.2438,  -1.9094, -4.0000, 0.0250,  0.3844,  0.2656, 1.0468, -0.3788, -2.4517, 1.4656},
    {-1.0500,  0.0289,  0.4260,  0.3590, -0.3250, 0.1156, 0.7781, 0.0025,  31.0625, -14.5000,
     -46.1148, 55.3750, -7.2312, 0.4050, 13.3500, 0.6234, 1.5000, -0.6426, 1.8564,  0.5636},
}};

// The clearness bins' upper limits (Perez 1990, table 1); the last bin is unbounded.
constexpr std::array<double, 7> kClearnessLimits{1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};

constexpr double kSolarConstant = 1367.0;  // W/m², as gendaymtx takes it
constexpr double kHighestSun = 87.0 * kPi / 180.0;
constexpr double kClearest = 12.0;

// Relative optical air mass: F. Kasten, 1966, as Perez 1990 and gendaymtx use it.
double air_mass(double zenith) {
  return 1.0 / (std::cos(zenith) + 0.15 * std::pow(93.885 - zenith * 180.0 / kPi, -1.253));
}

// The Earth's orbit's eccentricity correction (Spencer's series, as gendaymtx gives it).
double eccentricity(int day_of_year) {
  const double g = (day_of_year - 1.0) * 2.0 * kPi / 365.0;
  return 1.00011 + 0.034221 * std::cos(g) + 0.00128 * std::sin(g) + 0.000719 * std::cos(2.0 * g) +
         0.000077 * std::sin(2.0 * g);
}

double relative_luminance(const PerezParameters& p, double zeta, double gamma) {
  const double cos_gamma = std::cos(gamma);
  return (1.0 + p.a * std::exp(p.b / std::cos(zeta))) *
         (1.0 + p.c * std::exp(p.d * gamma) + p.e * cos_gamma * cos_gamma);
}

}  // namespace

PerezParameters perez_parameters(const SkyHour& hour) {
  PerezParameters p;
  const double zenith = kPi / 2.0 - std::min(hour.sun_altitude_rad, kHighestSun);
  const double dhi = hour.diffuse_horizontal_w_m2;
  const double z3 = 1.041 * zenith * zenith * zenith;
  p.clearness = std::min(((dhi + hour.direct_normal_w_m2) / dhi + z3) / (1.0 + z3), kClearest);
  p.brightness = dhi * air_mass(zenith) / (kSolarConstant * eccentricity(hour.day_of_year));
  p.bin = static_cast<int>(
      std::upper_bound(kClearnessLimits.begin(), kClearnessLimits.end(), p.clearness) -
      kClearnessLimits.begin());
  if (p.clearness > 1.065 && p.clearness < 2.8) p.brightness = std::max(p.brightness, 0.2);
  const std::array<double, 20>& x = kCoefficients[static_cast<std::size_t>(p.bin)];
  const double delta = p.brightness;
  const auto term = [&](int i) {
    return x[4 * i] + x[4 * i + 1] * zenith + delta * (x[4 * i + 2] + x[4 * i + 3] * zenith);
  };
  p.a = term(0);
  p.b = term(1);
  p.e = term(4);
  if (p.bin == 0) {  // 1993, eqs. 7 and 8
    p.c = std::exp(std::pow(delta * (x[8] + x[9] * zenith), x[10])) - x[11];
    p.d = -std::exp(delta * (x[12] + x[13] * zenith)) + x[14] + delta * x[15];
  } else {
    p.c = term(2);
    p.d = term(3);
  }
  return p;
}

PerezSky::PerezSky(std::span<const SkyPatch> patches) : patches_(patches) {
  horizontal_.reserve(patches.size());
  for (const SkyPatch& patch : patches) {
    horizontal_.push_back(patch_cosine_integral(patch, {0.0, 0.0, 1.0}));
    horizontal_sum_ += horizontal_.back();
  }
}

std::vector<double> PerezSky::radiance(const SkyHour& hour) const {
  const std::span<const SkyPatch> patches = patches_;
  const std::vector<double>& horizontal = horizontal_;
  std::vector<double> radiance(patches.size(), 0.0);
  // Where dhi is positive, 0 < ε (finite) and Δ is finite; no NaN reaches the radiances.
  const double dhi = hour.diffuse_horizontal_w_m2;
  if (!(dhi > 0.0)) return radiance;
  if (hour.sun_altitude_rad > 0.0) {
    const PerezParameters p = perez_parameters(hour);
    const double altitude = std::min(hour.sun_altitude_rad, kHighestSun);
    const glm::dvec3 sun{std::cos(altitude) * std::sin(hour.sun_azimuth_rad),
                         std::cos(altitude) * std::cos(hour.sun_azimuth_rad), std::sin(altitude)};
    double sum = 0.0;
    for (std::size_t k = 0; k < patches.size(); ++k) {
      const glm::dvec3& c = patches[k].centre;
      const double dot = std::clamp(c.x * sun.x + c.y * sun.y + c.z * sun.z, -1.0, 1.0);
      radiance[k] = std::max(
          0.0, relative_luminance(p, std::acos(std::clamp(c.z, -1.0, 1.0)), std::acos(dot)));
      sum += radiance[k] * horizontal[k];
    }
    if (sum > 0.0 && std::isfinite(sum)) {
      for (double& l : radiance) l *= dhi / sum;
      return radiance;
    }
  }
  // Isotropic: Σ_p I(p, up) is π up to rounding.
  std::fill(radiance.begin(), radiance.end(), dhi / horizontal_sum_);
  return radiance;
}

}  // namespace shadowgen::sky
