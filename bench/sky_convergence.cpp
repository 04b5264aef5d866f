// The sky view factor's error against closed forms per sky subdivision (bench/RESULTS.md,
// "Sky view factor: convergence"): the floor of street canyons of H/W 0.5, 1 and 2, and
// unobstructed faces of tilt 0° to 135°. Prints a Markdown table; its first argument, when
// given, is the largest Reinhart MF:N to run (default 16).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "scenes/street_canyon.h"
#include "shadowgen/sky/sky_exposure.h"

namespace {

using shadowgen::Scene;
namespace sky = shadowgen::sky;

double relative_error(double got, double expected) { return (got - expected) / expected; }

// A unit square facing south at tilt `tilt_deg`, alone.
Scene tilted(double tilt_deg) {
  const double b = tilt_deg * std::numbers::pi / 180.0;
  const glm::dvec3 s{0.0, 0.5 * std::cos(b), 0.5 * std::sin(b)}, x{0.5, 0.0, 0.0};
  Scene scene;
  scene.file = "tilted";
  shadowgen::Face face;
  face.id = "tilted";
  face.parts.push_back({{-s - x, -s + x, s + x, s - x}, {}});
  scene.faces.push_back(face);
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  const int most = argc > 1 ? std::atoi(argv[1]) : 16;
  const double heights[] = {0.5, 1.0, 2.0};
  const double tilts[] = {30.0, 90.0, 135.0};
  std::printf(
      "| subdivision | patches | canyon H/W 0.5 | H/W 1 | H/W 2 | tilt 30° (relative) | 90° | 135° "
      "|\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n = 1; n <= most; n = n < 8 ? n + 1 : n * 2) {
    sky::SkyOptions options;
    options.subdivisions = n;
    std::printf("| %s | %d |", n == 1 ? "tregenza (MF:1)" : ("MF:" + std::to_string(n)).c_str(),
                144 * n * n + 1);
    for (const double h : heights) {
      const sky::SkyExposure e = sky::sky_exposure(shadowgen::bench::street_canyon(h), options);
      std::printf(" %+.3f %% |",
                  100.0 * relative_error(sky::sky_view_factor(e, 0),
                                         shadowgen::bench::street_canyon_sky_view_factor(h)));
    }
    for (const double t : tilts) {
      const sky::SkyExposure e = sky::sky_exposure(tilted(t), options);
      const double expected = (1.0 + std::cos(t * std::numbers::pi / 180.0)) / 2.0;
      std::printf(" %+.1e |", relative_error(sky::sky_view_factor(e, 0), expected));
    }
    std::printf("\n");
    std::fflush(stdout);
  }
}
