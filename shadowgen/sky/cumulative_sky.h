#pragma once

// A cumulative sky (docs/radiation.md, "Cumulative sky"): the Perez sky of every hour of a
// period summed into one radiance per patch, each hour weighted by the hours it stands
// for, as Radiance's gendaymtx summed over its columns, and Ladybug's cumulative sky, give
// it. A face's diffuse irradiation over the period is then Σ_p W(f, p) × this
// (sky_exposure.h), linear in the hours as the sky is.

#include <span>
#include <vector>

#include "shadowgen/sky/perez_sky.h"

namespace shadowgen::sky {

// One hour of weather standing for `hours` hours of the period (a sun path's step).
struct WeightedSkyHour {
  SkyHour hour;
  double hours = 1.0;
};

// Σ over `hours` of sky.radiance(hour) × hours, per patch of `sky`: Wh/m²/sr. O(patches ×
// hours).
std::vector<double> cumulative_sky(const PerezSky& sky, std::span<const WeightedSkyHour> hours);

}  // namespace shadowgen::sky
