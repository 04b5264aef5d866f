#pragma once

// Sky view factors by several methods on the user's own scene (`shadowgen compare --sky`):
// the scene lit by the patches of Reinhart's MF:N (sky_lights.h), each method run in turn
// on it, its lit areas turned into view factors by the same weights (sky_exposure.h).

#include <functional>
#include <span>

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/sky/sky_comparison.h"

namespace shadowgen {

// The exact method, then each of `methods` (an exact one among them is the first trial,
// not run again), with `options` (sun paths summed into lit areas alone; its
// on_light_done counts the exact trial's patches). `on_trial`, where given, is called with
// each trial's method before it runs, the exact one first. Throws what shadows_by_method
// throws; std::invalid_argument for subdivisions outside reinhart_patches's range.
sky::SkyComparison compare_sky_methods(const Scene& scene, int subdivisions,
                                       std::span<const Method> methods, GenerateOptions options,
                                       const std::function<void(const Method&)>& on_trial = {});

}  // namespace shadowgen
