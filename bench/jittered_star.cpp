#include "bench/jittered_star.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>

namespace shadowgen::bench {
namespace {

using clipper::Loop2;
using clipper::Point2;

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kInnerRadiusRatio = 0.6;  // valley radius / tip radius of a star
constexpr double kHoleOrbit = 0.28;        // hole centre distance / radius
constexpr double kHoleRadius = 0.2;        // hole tip radius / radius
constexpr int kHoleArms = 5;

// Uniform in [0, 1) from the top 53 bits, the same on every platform.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Counter-clockwise star-shaped loop of n vertices about `centre`.
Loop2 jittered_star_loop(Point2 centre, double radius, int arms, double rotation, std::size_t n,
                         std::mt19937_64& rng) {
  const double step = kTwoPi / static_cast<double>(n);
  const double radial_jitter = std::min(0.1, 0.6 * step);
  const double arm_angle = kTwoPi / arms;
  Loop2 loop;
  loop.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = (static_cast<double>(i) + 0.35 * (2.0 * unit(rng) - 1.0)) * step;
    // Star profile: 1 at an arm tip, kInnerRadiusRatio half-way between two tips,
    // linear in the angle in between.
    const double phase = std::fmod(angle, arm_angle) / arm_angle;  // in [0, 1)
    const double profile = 1.0 - (1.0 - kInnerRadiusRatio) * (1.0 - std::abs(2.0 * phase - 1.0));
    const double r = radius * profile * (1.0 + radial_jitter * (2.0 * unit(rng) - 1.0));
    loop.push_back(
        {centre.x + r * std::cos(angle + rotation), centre.y + r * std::sin(angle + rotation)});
  }
  return loop;
}

}  // namespace

clipper::PolygonWithHoles2 jittered_star_with_holes(const JitteredStarSpec& spec) {
  if (spec.hole_count < 0 || spec.hole_count > 3 ||
      spec.vertex_count < 8 * static_cast<std::size_t>(spec.hole_count + 1)) {
    throw std::invalid_argument(
        "jittered_star_with_holes: need at most 3 holes and "
        "at least 8 vertices per loop");
  }
  std::mt19937_64 rng(spec.seed);
  const auto holes = static_cast<std::size_t>(spec.hole_count);
  const std::size_t hole_vertices = std::max<std::size_t>(4, spec.vertex_count / 8);

  clipper::PolygonWithHoles2 polygon;
  polygon.outer = jittered_star_loop(spec.centre, spec.radius, spec.arms, spec.rotation,
                                     spec.vertex_count - holes * hole_vertices, rng);
  for (std::size_t h = 0; h < holes; ++h) {
    const double orbit_angle =
        spec.rotation + kTwoPi * static_cast<double>(h) / static_cast<double>(holes);
    const Point2 hole_centre{spec.centre.x + kHoleOrbit * spec.radius * std::cos(orbit_angle),
                             spec.centre.y + kHoleOrbit * spec.radius * std::sin(orbit_angle)};
    Loop2 hole = jittered_star_loop(hole_centre, kHoleRadius * spec.radius, kHoleArms, orbit_angle,
                                    hole_vertices, rng);
    std::reverse(hole.begin(), hole.end());  // holes run clockwise
    polygon.holes.push_back(std::move(hole));
  }
  return polygon;
}

StarPair overlapping_star_pair(std::size_t vertex_count) {
  JitteredStarSpec subject;
  subject.centre = {0.0, 0.0};
  subject.radius = 1.0;
  subject.arms = 9;
  subject.rotation = 0.1;
  subject.vertex_count = vertex_count;
  subject.seed = 0x5EED0001;

  JitteredStarSpec clip;
  clip.centre = {0.45, 0.30};
  clip.radius = 1.05;
  clip.arms = 11;
  clip.rotation = 0.7;
  clip.vertex_count = vertex_count;
  clip.seed = 0x5EED0002;

  return {jittered_star_with_holes(subject), jittered_star_with_holes(clip)};
}

}  // namespace shadowgen::bench
