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

}  // namespace shadowgen::bench
