#pragma once

// Sampled lit-area estimator 1: a shadow map (Williams 1978, the depth-buffer method
// the shadow-volume papers compare against). The faces in the light's scope are
// rasterised from the light into a depth buffer of map_size × map_size texels (texel
// centres tested against each convex face's image; a directional light gets one
// orthographic map fitted to the scope's bounding box, a point light a cube map of six
// 90° perspective maps storing 1/z). Each receiving face's lit area is then estimated
// from k × k sample points (bench/sampled/face_samples.h): a sample is lit when its
// depth exceeds the map's by no more than a bias of (1 + min(tan θ, 10)) texel widths at
// the sample's depth, θ the angle between the face's normal and the light. Faces out of
// the light's scope or facing away get 0, as in the exact result.

#include <vector>

#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

// Estimated lit area per face of `scene`, for `light`.
std::vector<double> shadow_map_lit_areas(const Scene& scene, const Light& light, int map_size,
                                         int k);

}  // namespace shadowgen::bench
