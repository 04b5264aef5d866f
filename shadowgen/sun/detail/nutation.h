#pragma once

// Nutation in longitude and in obliquity, and the true obliquity of the ecliptic, as NREL's
// Solar Position Algorithm computes them (Reda & Andreas, NREL/TP-560-34302, 2008,
// section 3.4 and Table A4.3; Meeus, Astronomical Algorithms, chapter 22). Degrees.

namespace shadowgen::sun::detail {

struct Nutation {
  double longitude_deg = 0.0;  // Δψ
  double obliquity_deg = 0.0;  // Δε
};

// `jce`: Julian ephemeris centuries from J2000.0 (TT).
Nutation nutation(double jce);

// ε = ε0 + Δε, ε0 by Laskar's polynomial (valid for 10,000 years around J2000.0).
double true_obliquity_deg(double jme, const Nutation& n);

}  // namespace shadowgen::sun::detail
