#pragma once

// Triangles in an Intel Embree 3 hierarchy, and every triangle a segment meets: what the
// pictures made pixel by pixel share (pixel_surfaces.h: the surface seen through each
// pixel; detail/shadow_volumes.h: the shadow-volume faces an eye ray crosses).
//
// Embree works in floats. The triangles are stored relative to a centre chosen near them
// (a scene 1e8 from the origin keeps the precision of its own size), and the scene is
// built in robust (watertight) mode, so that a segment through an edge shared by two
// triangles cannot slip between them; it may then meet both (callers decide what a hit on
// a shared edge counts for). Every hit is reported through an intersection filter that
// rejects it, so the traversal goes on to the end of the segment: the hits of one query
// come in no particular order, and a triangle may in principle be reported twice.

#include <embree3/rtcore.h>

#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "shadowgen/sampled/part_triangles.h"

namespace shadowgen::view::detail {

// An Embree device (its thread pool and settings) for one picture.
class EmbreeDevice {
 public:
  // Throws std::runtime_error where Embree gives none.
  EmbreeDevice();
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  RTCDevice get() const { return device_; }

 private:
  RTCDevice device_;
};

// One meeting of a segment and a triangle: the triangle's index in the span the scene was
// built from, and the segment's parameter there (Embree's, in floats).
struct SegmentHit {
  unsigned triangle = 0;
  float t = 0.0f;
};

class TriangleScene {
 public:
  // The hierarchy of `triangles`, stored relative to `centre`, built on `device` (which
  // must outlive the scene). Throws std::runtime_error where Embree fails.
  TriangleScene(RTCDevice device, std::span<const sampled::Triangle3> triangles,
                const glm::dvec3& centre);
  ~TriangleScene();
  TriangleScene(const TriangleScene&) = delete;
  TriangleScene& operator=(const TriangleScene&) = delete;

  // Appends to `out` every triangle the points origin + t·direction, t in [tnear, tfar],
  // meet. Safe to call from several threads at once.
  void hits(const glm::dvec3& origin, const glm::dvec3& direction, double tnear, double tfar,
            std::vector<SegmentHit>& out) const;

  // The largest |coordinate| of the stored (centred) vertices: what float rounding of
  // the triangles is relative to.
  double magnitude() const { return magnitude_; }

 private:
  RTCScene scene_;
  glm::dvec3 centre_;
  double magnitude_ = 0.0;
};

}  // namespace shadowgen::view::detail
