#pragma once

// Stratified sample points over one face, and the per-part lit areas they estimate.
//
// Layout: a face's `count` points are shared among its parts that have area, each part
// getting one point and the rest shared in proportion to area (largest remainders, ties to
// the earlier part), so that every part with area has a sample however small it is: its
// estimate then never rests on a neighbour's points. A face with more parts with area than
// `count` gets one point per part, more than `count`. Within a part, its n points are laid
// out on the unit square cut into rows ⌊√n⌋ of n / rows cells (the first n mod rows rows
// one cell more), one point jittered uniformly inside each cell, and carried onto the part
// by an area-preserving map: the first coordinate picks a triangle by cumulative area
// (part_triangles.h), Shirley's square-to-triangle warp places the point in it. A cell
// covers 1/(rows × its row's cells) of the part's area, its point's weight.
//
// Estimate: a part's lit area is its area × Σ weight × lit / Σ weight over its points, lit
// the point's lit fraction in [0, 1] (1 or 0 for a shadow ray, the filtered fraction of a
// shadow map). The cells partition the part, and each point is uniform in its cell, so
// the estimate is unbiased over the jitter; a part wholly lit gets exactly its area, one
// wholly shadowed exactly 0, and the parts' values sum to the face's estimate by
// definition. The jitter comes from a fixed seed and the face's index: the same face gives
// the same points in every run, whatever the thread.

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "shadowgen/sampled/part_triangles.h"

namespace shadowgen::sampled {

struct FaceSample {
  glm::dvec3 point{0.0};
  double weight = 0.0;   // the fraction of its part's area its cell covers
  std::size_t part = 0;  // index among the face's parts
};

// How many of `count` points each part gets (0 for a part without area).
std::vector<int> samples_per_part(std::span<const PartTriangles> parts, int count);

// The points of the face whose parts are `parts`; `stream` (the face's index) varies the
// jitter from face to face. `out` is replaced; points are grouped by part, in part order.
void face_samples(std::span<const PartTriangles> parts, int count, std::uint64_t stream,
                  std::vector<FaceSample>& out);

// The estimated lit area of every part from its points' lit fractions, `lit` in parallel
// with `samples`; 0 for a part without points.
std::vector<double> part_lit_areas(std::span<const PartTriangles> parts,
                                   std::span<const FaceSample> samples,
                                   std::span<const double> lit);

}  // namespace shadowgen::sampled
