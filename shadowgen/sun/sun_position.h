#pragma once

// The sun's apparent position seen from a place on the Earth at an instant: NREL's Solar
// Position Algorithm (I. Reda and A. Andreas, "Solar Position Algorithm for Solar
// Radiation Applications", NREL/TP-560-34302, revised 2008), which the paper states to
// ±0.0003° in zenith and azimuth for the years -2000 to 6000. Implemented here rather than
// taken from Debian's libnova 0.16, whose solar longitude is 0.054° off at the paper's
// example (its azimuth 0.066°): beyond the 0.01° the format asks for.
//
// Conventions:
// - latitude north-positive, longitude east-positive, degrees; elevation above sea level
//   in metres (topocentric parallax, at most 0.0024°, is included);
// - azimuth clockwise from true north (east is 90°), in [0°, 360°);
// - elevation is the apparent one, above the horizon: topocentric, with the refraction of
//   an atmosphere at `pressure_hpa` and `temperature_c` (the standard atmosphere by
//   default: 1010 hPa, 10 °C), by Saemundsson's formula as the paper gives it. Refraction
//   is added only while the sun's upper limb is above the geometric horizon lowered by the
//   mean refraction there (true elevation at least -0.8333°); below it, the true elevation.
// - time is UT as a Julian day; `delta_t_s` is TT - UT in seconds. The position barely
//   depends on it (the sun moves 0.0007° along the ecliptic in a minute), so
//   delta_t_estimate() serves wherever ΔT is not known.
//
// Tested (tests/shadowgen/sun/sun_position_test.cpp) against the paper's own example
// (zenith 50.11162°, azimuth 194.34024°) to 1e-4°, Meeus's example 25.b (apparent right
// ascension and declination) to 1e-4°, and the instants of equinoxes and solstices that
// the US Naval Observatory publishes to 0.01°: right ascension a multiple of 90°,
// declination 0 or ±ε, the sun due east or west on the equator at an equinox, and at ε
// above the horizon from the pole at a solstice.

namespace shadowgen::sun {

struct Observer {
  double latitude_deg = 0.0;   // [-90, 90]
  double longitude_deg = 0.0;  // [-180, 180]
  double elevation_m = 0.0;
  double pressure_hpa = 1010.0;
  double temperature_c = 10.0;
};

struct SunPosition {
  double azimuth_deg = 0.0;    // topocentric, clockwise from true north
  double elevation_deg = 0.0;  // topocentric, apparent (refraction included)
  // Geocentric apparent equatorial coordinates (of date).
  double right_ascension_deg = 0.0;  // [0, 360)
  double declination_deg = 0.0;
};

SunPosition sun_position(const Observer& observer, double julian_day_ut, double delta_t_s);

// TT - UT in seconds for a (fractional) year: Espenak and Meeus's polynomials
// (NASA, "Polynomial Expressions for Delta T") from 1961 to 2150, their long-term
// parabola outside.
double delta_t_estimate(double year);

}  // namespace shadowgen::sun
