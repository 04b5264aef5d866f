#include "shadowgen/sky/patch_cosine.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shadowgen::sky {
namespace {

constexpr double kPi = std::numbers::pi;

// ∫ over φ in [φ0, φ1] of max(0, A cos(φ - ψ) + B), A >= 0, φ1 - φ0 <= 2π: the arc where
// the integrand is positive is ψ ± w, w = acos(-B/A), and F(x) = A sin x + B x integrates
// it on any piece of that arc (x = φ - ψ).
double positive_cosine_integral(double a_coefficient, double psi, double b, double phi0,
                                double phi1) {
  if (a_coefficient <= std::abs(b)) {  // one sign all round (A = 0 included)
    if (b <= 0.0) return 0.0;
    if (a_coefficient == 0.0) return b * (phi1 - phi0);
  }
  const double c = -b / a_coefficient;
  const double w = c <= -1.0 ? kPi : (c >= 1.0 ? 0.0 : std::acos(c));
  const auto f = [&](double x) { return a_coefficient * std::sin(x) + b * x; };
  // x runs over [s, s + Δφ] with s in [-π, π); the arcs [-w, w] and [2π - w, 2π + w] cover
  // all that interval meets, and when w = π they join without overlap.
  double s = std::remainder(phi0 - psi, 2.0 * kPi);
  if (s >= kPi) s -= 2.0 * kPi;
  const double e = s + (phi1 - phi0);
  double sum = 0.0;
  for (const double centre : {0.0, 2.0 * kPi}) {
    const double lo = std::max(s, centre - w), hi = std::min(e, centre + w);
    if (hi > lo) sum += f(hi - centre) - f(lo - centre);
  }
  return sum;
}

// ∫ over the patch's azimuths of cos a max(0, n·d) at altitude a.
double row_integral(const SkyPatch& patch, const glm::dvec3& n, double a) {
  // n·d = cos a (n_x sin φ + n_y cos φ) + n_z sin a = A cos(φ - ψ) + B.
  const double horizontal = std::hypot(n.x, n.y);
  const double psi = std::atan2(n.x, n.y);
  return std::cos(a) * positive_cosine_integral(std::cos(a) * horizontal, psi, n.z * std::sin(a),
                                                patch.azimuth_min, patch.azimuth_max);
}

double closed_form(const SkyPatch& p, const glm::dvec3& n) {
  const double a0 = p.altitude_min, a1 = p.altitude_max;
  const double k = (a1 - a0) / 2.0 + (std::sin(2.0 * a1) - std::sin(2.0 * a0)) / 4.0;
  const double s0 = std::sin(a0), s1 = std::sin(a1);
  return n.x * k * (std::cos(p.azimuth_min) - std::cos(p.azimuth_max)) +
         n.y * k * (std::sin(p.azimuth_max) - std::sin(p.azimuth_min)) +
         n.z * (p.azimuth_max - p.azimuth_min) * (s1 * s1 - s0 * s0) / 2.0;
}

// The least and most of n·d over an altitude edge (a fixed, φ in [φ0, φ1]) or a meridian
// edge (φ fixed, a in [a0, a1]): both are R cos(t - χ) over an interval of t, whose
// extremes lie at its ends or where t - χ is a multiple of π inside it.
struct Range {
  double low = 1.0, high = -1.0;
  void take(double v) {
    low = std::min(low, v);
    high = std::max(high, v);
  }
};

void cosine_range(double r, double chi, double t0, double t1, Range& range) {
  range.take(r * std::cos(t0 - chi));
  range.take(r * std::cos(t1 - chi));
  for (double k = std::ceil((t0 - chi) / kPi); chi + k * kPi <= t1; k += 1.0) {
    range.take(r * std::cos(k * kPi));
  }
}

// Where n·d lies on the patch: on its edges, and -1 or 1 where -n or n is inside it.
Range range_on_patch(const SkyPatch& p, const glm::dvec3& n) {
  Range range;
  const double horizontal = std::hypot(n.x, n.y);
  const double psi = std::atan2(n.x, n.y);
  const bool cap = p.azimuth_max - p.azimuth_min >= 2.0 * kPi;
  for (const double a : {p.altitude_min, p.altitude_max}) {
    // Along an altitude circle: cos a |n_xy| cos(φ - ψ) + n_z sin a.
    Range edge;
    cosine_range(std::cos(a) * horizontal, psi, p.azimuth_min, p.azimuth_max, edge);
    range.take(edge.low + n.z * std::sin(a));
    range.take(edge.high + n.z * std::sin(a));
  }
  if (!cap) {
    for (const double phi : {p.azimuth_min, p.azimuth_max}) {
      // Along a meridian: p cos a + n_z sin a = R cos(a - χ).
      const double along = n.x * std::sin(phi) + n.y * std::cos(phi);
      cosine_range(std::hypot(along, n.z), std::atan2(n.z, along), p.altitude_min, p.altitude_max,
                   range);
    }
  }
  for (const double sign : {-1.0, 1.0}) {
    const glm::dvec3 d = sign * n;
    const double a = std::asin(std::clamp(d.z, -1.0, 1.0));
    double phi = std::atan2(d.x, d.y);
    if (phi < p.azimuth_min) phi += 2.0 * kPi;
    const bool inside = a >= p.altitude_min && a <= p.altitude_max &&
                        (cap || (phi >= p.azimuth_min && phi <= p.azimuth_max));
    if (inside) range.take(sign);
  }
  return range;
}

}  // namespace

double patch_cosine_integral(const SkyPatch& patch, const glm::dvec3& normal) {
  const Range range = range_on_patch(patch, normal);
  if (range.low >= 0.0) return closed_form(patch, normal);
  if (range.high <= 0.0) return 0.0;
  const double da = patch.altitude_max - patch.altitude_min;
  const double dphi = patch.azimuth_max - patch.azimuth_min;
  const double bound_per_node = dphi * da * da / 4.0;
  const int nodes = std::max(
      1, static_cast<int>(std::ceil(bound_per_node / (kCutPatchTolerance * patch.solid_angle))));
  const double h = da / nodes;
  double sum = 0.0;
  for (int i = 0; i < nodes; ++i) {
    sum += row_integral(patch, normal, patch.altitude_min + (i + 0.5) * h);
  }
  return sum * h;
}

}  // namespace shadowgen::sky
