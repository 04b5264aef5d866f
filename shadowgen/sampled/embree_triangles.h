#pragma once

// Triangles in an Intel Embree 3 scene, built one way for everything that casts rays here
// (ray_caster.h: shadow rays; shadowgen/view: the surface seen through each pixel, the
// shadow-volume faces an eye ray crosses).
//
// Embree works in floats: each vertex is stored as (vertex − centre) rounded to float, so a
// scene far from the origin keeps the precision of its own size when `centre` is chosen
// near it. The scene is built in robust (watertight) mode, so that a ray through an edge
// shared by two triangles cannot slip between them. Triangle k of the span is primitive k
// of geometry 0.

#include <embree3/rtcore.h>

#include <glm/vec3.hpp>
#include <span>

#include "shadowgen/sampled/part_triangles.h"

namespace shadowgen::sampled {

// Throws std::runtime_error naming `what` where `device` holds an error.
void check_embree(RTCDevice device, const char* what);

struct EmbreeTriangles {
  RTCScene scene = nullptr;  // committed; the caller releases it (rtcReleaseScene)
  double magnitude = 0.0;    // the largest |coordinate| of the stored (centred) vertices
};

// The committed scene of `triangles` on `device`, relative to `centre`, `filter` (when not
// null) set as the geometry's intersection filter. Throws std::runtime_error where Embree
// fails, having released what it made.
EmbreeTriangles embree_triangles(RTCDevice device, std::span<const Triangle3> triangles,
                                 const glm::dvec3& centre, RTCFilterFunctionN filter = nullptr);

}  // namespace shadowgen::sampled
