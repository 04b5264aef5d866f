#pragma once

// Sampled lit-area estimator 2: shadow rays, the per-sample form of shadow-volume
// counting (Crow 1977; Bergeron 1986 counts, per point, the shadow-volume faces crossed
// between the eye and the point; equivalently the occluders crossed by the segment
// from the point to the light, which is what is counted here, exactly per sample: no
// map, no bias). Each receiving face's lit area is estimated from k × k sample points
// (bench/sampled/face_samples.h); a sample is lit when the segment to the light (for a
// directional light, the ray against its direction) crosses no face in the light's
// scope, other than at its own start (parameter below 1e-9 of the segment). Occluders are
// the scope's faces, fanned into triangles, in a bounding-volume hierarchy (median
// splits, any-hit traversal). Faces out of scope or facing away get 0.

#include <vector>

#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

std::vector<double> shadow_ray_lit_areas(const Scene& scene, const Light& light, int k);

}  // namespace shadowgen::bench
