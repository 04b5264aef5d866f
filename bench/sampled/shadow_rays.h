#pragma once

// A third opinion for mesh_bench --worst, beside the exact result and Embree: shadow rays in
// double precision, through a bounding-volume hierarchy of their own (median splits,
// any-hit traversal, Möller–Trumbore with edges and vertices counting as hits), that share
// neither Embree's single precision and origin offset nor the exact generator's clipping.
// The sample points are the product's own (shadowgen/sampled/face_samples.h: the very points
// its rays estimator casts from), and so is what counts: the light's scope
// (shadowgen/shadows/light_scope.h) and the parts' triangles (part_triangles.h). A sample
// on a part facing the light is lit when the segment to the light (for a directional light,
// a ray against its direction past every occluder) crosses no occluder's triangle other than
// at its own start (parameter below 1e-9 of the segment); no offset, no bias.

#include <cstddef>
#include <span>
#include <vector>

#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

// The estimated lit area of each of `faces` (indices into scene.faces) under `light`, from
// `samples` points per face.
std::vector<double> double_ray_lit_areas(const Scene& scene, const Light& light,
                                         std::span<const std::size_t> faces, int samples);

}  // namespace shadowgen::bench
