#pragma once

// A scene's lit areas by a sampled method (docs/scene-format.md, "Methods"), run through the
// exact generator's per-light loop (generate.h) so that sun paths, threads and progress work
// alike: each light's lit areas are an estimator's, and no lit polygon is made. The result
// holds the estimator's method (ShadowedScene::estimate); sun paths keep their instants' lit
// areas alone, never sun-hours regions, and there are no shards of a sampled run. What only
// the exact method makes (lit polygons, regions, shards) is not among the options at all.

#include <functional>
#include <vector>

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {

// A sampled method's estimate of lit areas (shadowgen/sampled/estimate.h's Estimator): the
// method and the numbers come from one object, so they cannot disagree.
class LitAreaEstimator {
 public:
  virtual ~LitAreaEstimator() = default;
  // The method estimated with: MethodKind::kRays or kShadowMap, never kExact.
  virtual const Method& method() const = 0;
  // The lit area of every part of every face under `light`, [face][part] in Scene::faces
  // order. Called from several threads at once.
  virtual std::vector<std::vector<double>> lit_areas(const Light& light) const = 0;
};

struct EstimateOptions {
  unsigned threads = 0;  // as GenerateOptions::threads
  std::function<void(std::size_t light, const LightStats&)> on_light_done;  // as there
};

// The lit areas of every (face, light) of `scene` as `estimator` finds them:
// ShadowedScene::estimate()'s lit_area for the lights that are no instant of a sun path, the
// paths' lit_area for their instants. Throws what the estimator throws.
GenerateResult estimate_shadows(const Scene& scene, const LitAreaEstimator& estimator,
                                const EstimateOptions& options = {});

}  // namespace shadowgen
