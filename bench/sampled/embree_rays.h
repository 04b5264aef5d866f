#pragma once

// The sampling baseline the exact generator is measured against on real meshes: Intel
// Embree 3 casting one shadow ray from each of k × k stratified sample points per face
// (bench/sampled/stratified_samples.h) towards the light, on one core. A face's lit area
// is its area times the fraction of its samples whose ray reaches the light unoccluded;
// a face turned away from the light, or out of its range, gets 0 (bench/sampled/
// light_scope.h, the spec's rules). Occluders are every face in the light's scope, front
// or back, fanned into triangles. The bounding-volume hierarchy is built inside each
// call, so a call costs what a fresh estimate costs; the device (Embree's thread pool
// and settings) is made once, as an application would.

#include <embree3/rtcore.h>

#include <vector>

#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

// rtcOccluded1 per ray, or rtcOccluded16 on packets of 16 rays of one face.
enum class RayCasting { kOneByOne, kPackets16 };

class EmbreeShadowRays {
 public:
  EmbreeShadowRays();  // a device limited to one thread
  ~EmbreeShadowRays();
  EmbreeShadowRays(const EmbreeShadowRays&) = delete;
  EmbreeShadowRays& operator=(const EmbreeShadowRays&) = delete;

  // Estimated lit area of every face of `scene` under `light`, in the scene's face order.
  std::vector<double> lit_areas(const Scene& scene, const Light& light, int k,
                                RayCasting casting = RayCasting::kOneByOne) const;

 private:
  RTCDevice device_;
};

}  // namespace shadowgen::bench
