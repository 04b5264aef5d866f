#pragma once

// Point lights against the supported range of depths (shadowgen/model/coordinate_range.h):
// a point light's nearest face may not be nearer than the floor of its views' near
// distance lets them see, 2√3 × 2^-450 (about 1.19e-135) of its farthest vertex's
// distance, or the near plane would cut faces off and the shadows would be wrong.

#include "shadowgen/model/scene.h"

namespace shadowgen::scene::detail {

// Throws InputError naming the nearest face's file and id, the light and both distances
// where a point light of `scene` is nearer to a face than lamp_depths_supported allows.
// The faces are all the scene's: a subset (the faces within a light's range) is never
// refused where they all pass.
void check_lamp_depths(const Scene& scene);

}  // namespace shadowgen::scene::detail
