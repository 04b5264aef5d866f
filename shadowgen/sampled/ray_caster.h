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
//
// Packets. The rays of one face start close together and head the same way (all to the
// sun, or all to one lamp): the coherent case Embree's ray packets are made for, one
// traversal of the hierarchy for the whole packet. A caster casts in packets of the widest
// width Embree traverses natively on this CPU (its device properties: 16 with AVX-512, 8
// with AVX2, 4 with SSE; one by one where it has none). A ray in a packet has the origin,
// direction, tnear and tfar it has cast alone: only the call differs, and the answers are
// the same ray for ray (tests/shadowgen/sampled/ray_caster_test.cpp).

#include <embree3/rtcore.h>

#include <glm/vec3.hpp>
#include <span>

#include "shadowgen/model/scene.h"
#include "shadowgen/sampled/part_triangles.h"

namespace shadowgen::sampled {

// Float spacings of the scene's largest |coordinate| a ray starts off its part.
inline constexpr double kOffsetUlps = 8.0;

// How a batch of rays is handed to Embree: one rtcOccluded1 per ray, or in packets
// (rtcOccluded16, 8 or 4, packet_width()). The same answers either way.
enum class Casting : unsigned char { kOneByOne, kPackets };

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

  // out[i] = lit(light, points[i], normals[i]) for every i, the rays cast as `casting`
  // says. The spans have one size. Safe to call from several threads at once.
  void lit(const Light& light, std::span<const glm::dvec3> points,
           std::span<const glm::dvec3> normals, std::span<double> out, Casting casting) const;

  // The rays per packet of Casting::kPackets: 16, 8 or 4, or 1 (one by one) where Embree
  // traverses no packets natively on this CPU.
  int packet_width() const { return packet_width_; }

  // How far rays start off their part: kOffsetUlps float spacings of the scene's largest
  // |coordinate|.
  double offset() const { return offset_; }

 private:
  RTCScene scene_;
  double offset_ = 0.0;
  int packet_width_ = 1;
};

}  // namespace shadowgen::sampled
