#include "shadowgen/sun/sun_position.h"

#include <cmath>
#include <numbers>

#include "detail/earth_periodic_terms.h"
#include "detail/nutation.h"

namespace shadowgen::sun {
namespace {

constexpr double kJ2000 = 2451545.0;

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }
double degrees(double radians) { return radians * (180.0 / std::numbers::pi); }

double wrap_360(double degrees) {
  const double wrapped = std::fmod(degrees, 360.0);
  return wrapped < 0.0 ? wrapped + 360.0 : wrapped;
}

struct GeocentricSun {
  double right_ascension_deg;
  double declination_deg;
  double radius_au;  // the Earth's distance from the sun
};

// The paper's steps 3.2 to 3.8: the geocentric apparent position, from the Earth's
// heliocentric one, nutation and aberration.
GeocentricSun geocentric_sun(double jme, double epsilon_deg, const detail::Nutation& n) {
  const detail::HeliocentricPosition earth = detail::earth_heliocentric(jme);
  const double theta_deg = wrap_360(degrees(earth.longitude_rad) + 180.0);
  const double beta = -earth.latitude_rad;
  const double aberration_deg = -20.4898 / (3600.0 * earth.radius_au);
  const double lambda = radians(theta_deg + n.longitude_deg + aberration_deg);
  const double epsilon = radians(epsilon_deg);
  const double alpha = std::atan2(
      std::sin(lambda) * std::cos(epsilon) - std::tan(beta) * std::sin(epsilon), std::cos(lambda));
  const double delta = std::asin(std::sin(beta) * std::cos(epsilon) +
                                 std::cos(beta) * std::sin(epsilon) * std::sin(lambda));
  return {wrap_360(degrees(alpha)), degrees(delta), earth.radius_au};
}

// Step 3.8: apparent sidereal time at Greenwich, degrees.
double apparent_sidereal_time_deg(double jd, double epsilon_deg, const detail::Nutation& n) {
  const double jc = (jd - kJ2000) / 36525.0;
  const double mean = 280.46061837 + 360.98564736629 * (jd - kJ2000) + 0.000387933 * jc * jc -
                      jc * jc * jc / 38710000.0;
  return wrap_360(mean) + n.longitude_deg * std::cos(radians(epsilon_deg));
}

}  // namespace

SunPosition sun_position(const Observer& observer, double julian_day_ut, double delta_t_s) {
  const double jde = julian_day_ut + delta_t_s / 86400.0;
  const double jce = (jde - kJ2000) / 36525.0;
  const double jme = jce / 10.0;
  const detail::Nutation n = detail::nutation(jce);
  const double epsilon_deg = detail::true_obliquity_deg(jme, n);
  const GeocentricSun sun = geocentric_sun(jme, epsilon_deg, n);

  // Steps 3.9 to 3.12: the local hour angle, and the parallax of an observer on the
  // Earth's ellipsoid (flattening 1 - 0.99664719, equatorial radius 6378140 m).
  const double hour_angle =
      radians(wrap_360(apparent_sidereal_time_deg(julian_day_ut, epsilon_deg, n) +
                       observer.longitude_deg - sun.right_ascension_deg));
  const double xi = radians(8.794 / (3600.0 * sun.radius_au));
  const double phi = radians(observer.latitude_deg);
  const double u = std::atan(0.99664719 * std::tan(phi));
  const double x = std::cos(u) + observer.elevation_m / 6378140.0 * std::cos(phi);
  const double y = 0.99664719 * std::sin(u) + observer.elevation_m / 6378140.0 * std::sin(phi);
  const double delta = radians(sun.declination_deg);
  const double denominator = std::cos(delta) - x * std::sin(xi) * std::cos(hour_angle);
  const double delta_alpha = std::atan2(-x * std::sin(xi) * std::sin(hour_angle), denominator);
  const double delta_prime =
      std::atan2((std::sin(delta) - y * std::sin(xi)) * std::cos(delta_alpha), denominator);
  const double h_prime = hour_angle - delta_alpha;

  // Steps 3.14 to 3.15: elevation with refraction, azimuth from north.
  const double e0 = degrees(std::asin(std::sin(phi) * std::sin(delta_prime) +
                                      std::cos(phi) * std::cos(delta_prime) * std::cos(h_prime)));
  constexpr double kSunRadiusDeg = 0.26667;
  constexpr double kHorizonRefractionDeg = 0.5667;
  double refraction = 0.0;
  if (e0 >= -(kSunRadiusDeg + kHorizonRefractionDeg)) {
    refraction = observer.pressure_hpa / 1010.0 * 283.0 / (273.0 + observer.temperature_c) * 1.02 /
                 (60.0 * std::tan(radians(e0 + 10.3 / (e0 + 5.11))));
  }
  const double gamma = std::atan2(
      std::sin(h_prime), std::cos(h_prime) * std::sin(phi) - std::tan(delta_prime) * std::cos(phi));

  SunPosition position;
  position.azimuth_deg = wrap_360(degrees(gamma) + 180.0);
  position.elevation_deg = e0 + refraction;
  position.right_ascension_deg = sun.right_ascension_deg;
  position.declination_deg = sun.declination_deg;
  return position;
}

double delta_t_estimate(double year) {
  const double u = (year - 1820.0) / 100.0;
  const double long_term = -20.0 + 32.0 * u * u;
  if (year >= 1961.0 && year < 1986.0) {
    const double t = year - 1975.0;
    return 45.45 + 1.067 * t - t * t / 260.0 - t * t * t / 718.0;
  }
  if (year >= 1986.0 && year < 2005.0) {
    const double t = year - 2000.0;
    return 63.86 +
           t * (0.3345 + t * (-0.060374 + t * (0.0017275 + t * (0.000651814 + t * 0.00002373599))));
  }
  if (year >= 2005.0 && year < 2050.0) {
    const double t = year - 2000.0;
    return 62.92 + 0.32217 * t + 0.005589 * t * t;
  }
  if (year >= 2050.0 && year <= 2150.0) return long_term - 0.5628 * (2150.0 - year);
  return long_term;
}

}  // namespace shadowgen::sun
