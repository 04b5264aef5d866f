#pragma once

// Sampled estimates of lit areas (docs/scene-format.md, "Methods"): what a user trades
// exactness for speed with, measured against the exact generator on their own scene.
// Both methods place stratified sample points on every face that can receive the light
// (face_samples.h) and decide each point lit or not:
//   - rays (MethodKind::kRays): a shadow ray from the point towards the light, cast with
//     Intel Embree against every part the light takes into account;
//   - shadow map (MethodKind::kShadowMap): the point's depth from the light against a
//     depth map rendered from it, with percentage-closer filtering.
// The light's scope is the exact generator's (shadowgen/shadows/light_scope.h): a point
// light's range.end drops the faces wholly beyond it as receivers, and as occluders too
// unless they stand near enough to shadow a receiver (the spec: a face inside the range
// takes the shadows of occluders beyond it); a part turned away from the light (or seeing
// it edge-on) gets no lit area and still occludes. An estimate has no lit polygons, only
// areas.

#include <cstddef>
#include <memory>
#include <vector>

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/estimate_shadows.h"

namespace shadowgen::sampled {

// How shadow rays are handed to Embree (ray_caster.h).
enum class Casting : unsigned char;

// The estimated lit area of every part of every face, [face][part], in Scene::faces order.
using PartLitAreas = std::vector<std::vector<double>>;

class Estimator final : public LitAreaEstimator {
 public:
  // `method` is kRays or kShadowMap (std::invalid_argument otherwise, or for samples or a
  // resolution out of range). `scene` must outlive the estimator. Lights may be estimated
  // from several threads at once.
  Estimator(const Scene& scene, const Method& method);
  ~Estimator() override;
  Estimator(const Estimator&) = delete;
  Estimator& operator=(const Estimator&) = delete;

  // Lit area per part of every face under `light`. The same light gives the same numbers
  // in every run and on any number of threads.
  PartLitAreas lit_areas(const Light& light) const override;

  // The method given.
  const Method& method() const override;

 private:
  // Internal, for the benchmarks (ray_caster.h): whether a rays estimator casts a face's
  // rays in packets (the default) or one by one, the same numbers either way. Call it before
  // any lit_areas; found by argument-dependent lookup.
  friend void set_casting(Estimator& estimator, Casting casting);

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowgen::sampled
