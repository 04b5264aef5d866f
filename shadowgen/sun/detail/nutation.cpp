#include "detail/nutation.h"

#include <cmath>
#include <iterator>
#include <numbers>

namespace shadowgen::sun::detail {
namespace {

// Multiples of D, M, M', F and Ω in each term's argument, and its coefficients
// (Δψ = (a + b·JCE) sin(arg), Δε = (c + d·JCE) cos(arg), in 0.0001″).
struct Term {
  int d, m, mp, f, omega;
  double a, b, c, dd;
};

constexpr Term kTerms[] = {
    {0, 0, 0, 0, 1, -171996, -174.2, 92025, 8.9},
    {-2, 0, 0, 2, 2, -13187, -1.6, 5736, -3.1},
    {0, 0, 0, 2, 2, -2274, -0.2, 977, -0.5},
    {0, 0, 0, 0, 2, 2062, 0.2, -895, 0.5},
    {0, 1, 0, 0, 0, 1426, -3.4, 54, -0.1},
    {0, 0, 1, 0, 0, 712, 0.1, -7, 0},
    {-2, 1, 0, 2, 2, -517, 1.2, 224, -0.6},
    {0, 0, 0, 2, 1, -386, -0.4, 200, 0},
    {0, 0, 1, 2, 2, -301, 0, 129, -0.1},
    {-2, -1, 0, 2, 2, 217, -0.5, -95, 0.3},
    {-2, 0, 1, 0, 0, -158, 0, 0, 0},
    {-2, 0, 0, 2, 1, 129, 0.1, -70, 0},
    {0, 0, -1, 2, 2, 123, 0, -53, 0},
    {2, 0, 0, 0, 0, 63, 0, 0, 0},
    {0, 0, 1, 0, 1, 63, 0.1, -33, 0},
    {2, 0, -1, 2, 2, -59, 0, 26, 0},
    {0, 0, -1, 0, 1, -58, -0.1, 32, 0},
    {0, 0, 1, 2, 1, -51, 0, 27, 0},
    {-2, 0, 2, 0, 0, 48, 0, 0, 0},
    {0, 0, -2, 2, 1, 46, 0, -24, 0},
    {2, 0, 0, 2, 2, -38, 0, 16, 0},
    {0, 0, 2, 2, 2, -31, 0, 13, 0},
    {0, 0, 2, 0, 0, 29, 0, 0, 0},
    {-2, 0, 1, 2, 2, 29, 0, -12, 0},
    {0, 0, 0, 2, 0, 26, 0, 0, 0},
    {-2, 0, 0, 2, 0, -22, 0, 0, 0},
    {0, 0, -1, 2, 1, 21, 0, -10, 0},
    {0, 2, 0, 0, 0, 17, -0.1, 0, 0},
    {2, 0, -1, 0, 1, 16, 0, -8, 0},
    {-2, 2, 0, 2, 2, -16, 0.1, 7, 0},
    {0, 1, 0, 0, 1, -15, 0, 9, 0},
    {-2, 0, 1, 0, 1, -13, 0, 7, 0},
    {0, -1, 0, 0, 1, -12, 0, 6, 0},
    {0, 0, 2, -2, 0, 11, 0, 0, 0},
    {2, 0, -1, 2, 1, -10, 0, 5, 0},
    {2, 0, 1, 2, 2, -8, 0, 3, 0},
    {0, 1, 0, 2, 2, 7, 0, -3, 0},
    {-2, 1, 1, 0, 0, -7, 0, 0, 0},
    {0, -1, 0, 2, 2, -7, 0, 3, 0},
    {2, 0, 0, 2, 1, -7, 0, 3, 0},
    {2, 0, 1, 0, 0, 6, 0, 0, 0},
    {-2, 0, 2, 2, 2, 6, 0, -3, 0},
    {-2, 0, 1, 2, 1, 6, 0, -3, 0},
    {2, 0, -2, 0, 1, -6, 0, 3, 0},
    {2, 0, 0, 0, 1, -6, 0, 3, 0},
    {0, -1, 1, 0, 0, 5, 0, 0, 0},
    {-2, -1, 0, 2, 1, -5, 0, 3, 0},
    {-2, 0, 0, 0, 1, -5, 0, 3, 0},
    {0, 0, 2, 2, 1, -5, 0, 3, 0},
    {-2, 0, 2, 0, 1, 4, 0, 0, 0},
    {-2, 1, 0, 2, 1, 4, 0, 0, 0},
    {0, 0, 1, -2, 0, 4, 0, 0, 0},
    {-1, 0, 1, 0, 0, -4, 0, 0, 0},
    {-2, 1, 0, 0, 0, -4, 0, 0, 0},
    {1, 0, 0, 0, 0, -4, 0, 0, 0},
    {0, 0, 1, 2, 0, 3, 0, 0, 0},
    {0, 0, -2, 2, 2, -3, 0, 0, 0},
    {-1, -1, 1, 0, 0, -3, 0, 0, 0},
    {0, 1, 1, 0, 0, -3, 0, 0, 0},
    {0, -1, 1, 2, 2, -3, 0, 0, 0},
    {2, -1, -1, 2, 2, -3, 0, 0, 0},
    {0, 0, 3, 2, 2, -3, 0, 0, 0},
    {2, -1, 0, 2, 2, -3, 0, 0, 0},
};
static_assert(std::size(kTerms) == 63);

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

// a + b·T + c·T² + T³/d, degrees.
double argument(double t, double a, double b, double c, double d) {
  return a + t * (b + t * (c + t / d));
}

}  // namespace

Nutation nutation(double jce) {
  const double d = argument(jce, 297.85036, 445267.111480, -0.0019142, 189474.0);
  const double m = argument(jce, 357.52772, 35999.050340, -0.0001603, -300000.0);
  const double mp = argument(jce, 134.96298, 477198.867398, 0.0086972, 56250.0);
  const double f = argument(jce, 93.27191, 483202.017538, -0.0036825, 327270.0);
  const double omega = argument(jce, 125.04452, -1934.136261, 0.0020708, 450000.0);
  double psi = 0.0;
  double epsilon = 0.0;
  for (const Term& t : kTerms) {
    const double arg = radians(t.d * d + t.m * m + t.mp * mp + t.f * f + t.omega * omega);
    psi += (t.a + t.b * jce) * std::sin(arg);
    epsilon += (t.c + t.dd * jce) * std::cos(arg);
  }
  return {psi / 36000000.0, epsilon / 36000000.0};
}

double true_obliquity_deg(double jme, const Nutation& n) {
  // ε0 in arcseconds, a polynomial in U = JME / 10 (Laskar 1986).
  constexpr double kCoefficients[] = {84381.448, -4680.93, -1.55, 1999.25, 51.38, -249.67,
                                      -39.05,    7.12,     27.87, 5.79,    2.45};
  const double u = jme / 10.0;
  double epsilon0 = 0.0;
  for (auto it = std::rbegin(kCoefficients); it != std::rend(kCoefficients); ++it) {
    epsilon0 = epsilon0 * u + *it;
  }
  return epsilon0 / 3600.0 + n.obliquity_deg;
}

}  // namespace shadowgen::sun::detail
