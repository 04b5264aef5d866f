#pragma once

// A scene's shadows by a chosen method (docs/scene-format.md, "Methods"): the exact
// generator's, or a sampled estimate's (shadowgen/sampled/estimate.h) run through the same
// per-light loop, so that sun paths, threads and progress work alike for every method.

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {

// generate_shadows(scene, options) with options.method and options.estimate set for
// `method`. Throws what generate_shadows throws, and std::invalid_argument for a sampled
// method with a shard or kept instant polygons (the command line refuses them first).
GenerateResult shadows_by_method(const Scene& scene, const Method& method, GenerateOptions options);
// The same on a scene the result takes over where the method is exact (no copy of it).
GenerateResult shadows_by_method(Scene&& scene, const Method& method, GenerateOptions options);

}  // namespace shadowgen
