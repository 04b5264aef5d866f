#pragma once

// A scene's shadows by a chosen method (docs/scene-format.md, "Methods"): the exact
// generator's (shadows/generate.h), or a sampled estimate's (shadowgen/sampled/estimate.h)
// run through the same per-light loop (shadows/estimate_shadows.h), so that sun paths,
// threads and progress work alike for every method. Each method takes its own options:
// what only the exact method makes (lit polygons, sun-hours regions, shards) cannot be
// asked of a sampled one.

#include <variant>

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/estimate_shadows.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {

// A sampled method (MethodKind::kRays or kShadowMap) and the options its run takes.
struct SampledRun {
  Method method;
  EstimateOptions options;
};

// The exact method with its options, or a sampled one.
using MethodRun = std::variant<GenerateOptions, SampledRun>;

// The shadows of `scene` by `run`. Throws what generate_shadows throws, and, for a sampled
// run, std::invalid_argument where its method is exact or its numbers out of range
// (sampled::Estimator).
GenerateResult shadows_by_method(const Scene& scene, const MethodRun& run);
// The same on a scene the result takes over where the run is exact (no copy of it).
GenerateResult shadows_by_method(Scene&& scene, const MethodRun& run);

// The run of `method` with `options`, which are the exact method's; a sampled method takes
// their threads and on_light_done alone, its sun paths summed into lit areas alone. Where
// settings of every method arrive together (the library's GenerateSettings) this is where
// they part. Throws std::invalid_argument for a sampled method with kept instant polygons
// or a shard, which only the exact method makes.
MethodRun method_run(const Method& method, GenerateOptions options);

}  // namespace shadowgen
