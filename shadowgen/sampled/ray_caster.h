#pragma once

// Shadow rays with Intel Embree 3: a sample is lit when the segment from it to a point
// light (the ray against a directional light's direction) crosses no occluder. The
// occluders are the triangles of every part the light takes into account (light_scope.h),
// front or back, receivers included; Embree traverses a bounding-volume hierarchy built
// once per occluder set, in single precision, in robust (watertight) mode so that a ray
// through an edge shared by two triangles of one part cannot slip between them.
//
// Tolerances. Embree works in floats: rounding an occluder's vertices moves each by at
// most half a float spacing of the scene's largest |coordinate| M, and so any point of a
// rounded triangle, a convex combination of them, lies within (√3/2)·2^-24·M of the exact
// one, wherever the triangle is. A ray therefore starts off its sample's part, along the
// part's normal towards the light (the front side: only parts facing the light are
// sampled), by kOffsetUlps float spacings of M: past the part itself and every part
// coplanar with it, as rounded, and Embree's own rounding (coplanar polygons do not
// shadow each other, the spec says). The offset is kept that small on purpose: a ray
// leaving at a grazing angle θ passes an occluder next to its part (across a concave edge)
// offset / sin θ too high, lighting what the exact generator shades. A point light's
// segment ends the same offset short of the light, so that an occluder through the
// light's position (the light in its plane or on its boundary) meets the segment only at
// its end and does not block it, as the spec settles; one behind the light never counts.

#include <embree3/rtcore.h>

#include <glm/vec3.hpp>
#include <span>

#include "shadowgen/model/scene.h"
#include "shadowgen/sampled/part_triangles.h"

namespace shadowgen::sampled {

// Float spacings of the scene's largest |coordinate| a ray starts off its part.
inline constexpr double kOffsetUlps = 8.0;

class RayCaster {
 public:
  // The hierarchy of `occluders`, built on `device` (which must outlive the caster).
  // Throws std::runtime_error where Embree fails.
  RayCaster(RTCDevice device, std::span<const Triangle3> occluders);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Whether `point`, on a part whose unit front normal is `normal` and whose front side
  // the light reaches, is lit: 1 or 0. Safe to call from several threads at once.
  double lit(const Light& light, const glm::dvec3& point, const glm::dvec3& normal) const;

  // How far rays start off their part: kOffsetUlps float spacings of the scene's largest
  // |coordinate|.
  double offset() const { return offset_; }

 private:
  RTCScene scene_;
  double offset_ = 0.0;
};

}  // namespace shadowgen::sampled
