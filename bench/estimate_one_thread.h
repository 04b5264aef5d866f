#pragma once

// shadowgen's sampled estimate as the benchmarks time it against the exact result
// (exact_one_thread.h): the product's estimator (shadowgen/sampled/estimate.h), one thread
// (Embree's hierarchy builds included: they run on the calling task arena's threads), made
// from the scene inside the call, so that a call costs what a fresh estimate costs; the
// lit areas of each face's parts summed.

#include <tbb/task_arena.h>

#include <vector>

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/sampled/estimate.h"
#include "shadowgen/sampled/ray_caster.h"

namespace shadowgen::bench {

// Estimated lit area per face of `scene` under its first light; `casting` is how a rays
// estimator hands its rays to Embree (the same numbers either way).
inline std::vector<double> estimate_one_thread(
    const Scene& scene, const Method& method,
    sampled::Casting casting = sampled::Casting::kPackets) {
  tbb::task_arena arena(1);
  return arena.execute([&] {
    sampled::Estimator estimator(scene, method);
    set_casting(estimator, casting);
    const sampled::PartLitAreas parts = estimator.lit_areas(scene.lights.at(0));
    std::vector<double> lit(parts.size(), 0.0);
    for (std::size_t f = 0; f < parts.size(); ++f) {
      for (double a : parts[f]) lit[f] += a;
    }
    return lit;
  });
}

}  // namespace shadowgen::bench
