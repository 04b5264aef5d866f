#pragma once

// Sample points on a face: the centres of a k × k grid of cells over the face's bounding
// rectangle in its own plane (axes along its first edge and normal × that edge, so a
// rectangle is covered exactly by the grid), keeping the centres inside the face. For
// the benchmark scenes' rectangles that is all k² of them, each standing for 1/k² of
// the face's area.

#include <glm/vec3.hpp>
#include <vector>

#include "bench/sampled/light_scope.h"

namespace shadowgen::bench {

void face_samples(const ConvexFace& face, int k, std::vector<glm::dvec3>& out);

// Every receiving face's lit area estimated from its k × k samples: the face's area times
// the fraction of samples for which lit(sample, face) holds; 0 for faces that do not
// receive the light.
template <typename Lit>
std::vector<double> sampled_lit_areas(const LightScope& scope, int k, Lit lit) {
  std::vector<double> areas(scope.faces.size(), 0.0);
  std::vector<glm::dvec3> samples;
  for (std::size_t f = 0; f < scope.faces.size(); ++f) {
    if (!scope.receives[f]) continue;
    const ConvexFace& face = scope.faces[f];
    face_samples(face, k, samples);
    if (samples.empty()) continue;
    std::size_t hits = 0;
    for (const glm::dvec3& p : samples) {
      if (lit(p, face)) ++hits;
    }
    areas[f] = face.area * static_cast<double>(hits) / static_cast<double>(samples.size());
  }
  return areas;
}

}  // namespace shadowgen::bench
