#pragma once

// Stratified sample points on a convex face: the unit square cut into k × k strata, one
// point jittered inside each, carried onto the face by an area-preserving map (the face
// fanned into triangles from its first vertex; the square's first coordinate picks the
// triangle by cumulative area, then Shirley's square-to-triangle warp places the point).
// Every one of the k² points stands for 1/k² of the face's area, whatever its shape,
// unlike face_samples' grid over the bounding rectangle, which keeps only the centres
// that fall inside and so gives a triangle about half as many. The jitter comes from a
// fixed seed: the same face gives the same points in every run.

#include <glm/vec3.hpp>
#include <vector>

namespace shadowgen::bench {

// `loop` is convex, at least 3 vertices; `out` is replaced by the k² points.
void stratified_samples(const std::vector<glm::dvec3>& loop, int k, std::vector<glm::dvec3>& out);

}  // namespace shadowgen::bench
