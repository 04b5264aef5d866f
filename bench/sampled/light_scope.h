#pragma once

// What the sampled estimators share with the exact generator's rules (the spec's meaning
// of "lit"): which faces a light takes into account (a point light's range.end drops a
// face wholly beyond it, as receiver and as occluder) and which of those can be lit at
// all (front side towards the light). Faces must be single convex polygons without holes
// (the benchmark scenes' rectangles); anything else throws.

#include <glm/vec3.hpp>
#include <vector>

#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

struct ConvexFace {
  std::vector<glm::dvec3> loop;  // counter-clockwise seen from the front
  glm::dvec3 normal{0.0};        // unit, front side
  double area = 0.0;
};

struct LightScope {
  std::vector<ConvexFace> faces;  // every face of the scene, in order
  std::vector<bool> present;      // within range: receiver and occluder
  std::vector<bool> receives;     // present and facing the light
  glm::dvec3 lo{0.0}, hi{0.0};    // bounding box of the present faces
};

LightScope light_scope(const Scene& scene, const Light& light);

// Direction from p towards the light, not normalised (for a directional light, minus its
// direction).
glm::dvec3 towards_light(const Light& light, const glm::dvec3& p);

}  // namespace shadowgen::bench
