#include "shadowgen/sky/sky_comparison.h"

#include <cmath>

namespace shadowgen::sky {

SkyErrors sky_errors(const SkyComparison& comparison, std::size_t trial) {
  const std::vector<double>& area = comparison.area;
  const std::vector<double>& exact = comparison.trials.at(0).sky_view_factor;
  const std::vector<double>& estimate = comparison.trials.at(trial).sky_view_factor;
  SkyErrors out;
  double sum = 0.0, relative_sum = 0.0;
  std::size_t faces = 0, relative_faces = 0;
  for (std::size_t f = 0; f < exact.size(); ++f) {
    if (area[f] <= 0.0) continue;
    const double error = std::fabs(estimate[f] - exact[f]);
    sum += error;
    ++faces;
    if (error > out.max_error) {
      out.max_error = error;
      out.worst_face = f;
    }
    if (exact[f] > 0.0) {
      const double relative = error / exact[f];
      relative_sum += relative;
      ++relative_faces;
      if (relative > out.max_relative_error) out.max_relative_error = relative;
    }
  }
  if (faces > 0) out.mean_error = sum / static_cast<double>(faces);
  if (relative_faces > 0) {
    out.mean_relative_error = relative_sum / static_cast<double>(relative_faces);
  }
  return out;
}

}  // namespace shadowgen::sky
