#pragma once

// Sky view factors by several methods on one scene (`shadowgen compare --sky`;
// shadowgen/pipeline/sky_method_comparison.h makes them): the exact method's, from the exact
// lit area of every face under every patch's light, and sampled methods' estimates of the
// same lit areas (rays: a shadow ray from each sample point on a face towards each patch's
// centre), through the same weights (sky_exposure.h), with each one's error.

#include <cstddef>
#include <vector>

#include "shadowgen/model/method.h"

namespace shadowgen::sky {

struct SkyTrial {
  Method method;
  double seconds = 0.0;                 // wall time of its lit areas and view factors
  std::vector<double> sky_view_factor;  // [face], sky_exposure.h's
  bool pareto = false;                  // by the mean absolute error (mark_pareto)
};

struct SkyComparison {
  int subdivisions = 0;          // Reinhart MF:N of the patches
  std::vector<double> area;      // [face]
  std::vector<SkyTrial> trials;  // exact first, then the methods in the order given
};

// A trial's view factors against the exact trial's, over the faces with area:
// the mean and largest |SVF − exact SVF|, and relative to the exact one over the faces
// whose exact SVF is positive; worst_face is where the absolute error is largest.
struct SkyErrors {
  double mean_error = 0.0, max_error = 0.0;
  double mean_relative_error = 0.0, max_relative_error = 0.0;
  std::size_t worst_face = 0;
};

SkyErrors sky_errors(const SkyComparison& comparison, std::size_t trial);

}  // namespace shadowgen::sky
