#include "shadowgen/sky/cumulative_sky.h"

namespace shadowgen::sky {

std::vector<double> cumulative_sky(const PerezSky& sky, std::span<const WeightedSkyHour> hours) {
  std::vector<double> sum(sky.horizontal().size(), 0.0);
  for (const WeightedSkyHour& weighted : hours) {
    const std::vector<double> radiance = sky.radiance(weighted.hour);
    for (std::size_t p = 0; p < sum.size(); ++p) sum[p] += radiance[p] * weighted.hours;
  }
  return sum;
}

}  // namespace shadowgen::sky
