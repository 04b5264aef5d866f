#pragma once

// The centre of a scene's bounding box: what output in single precision (pixels, glTF's
// float32 positions) takes its coordinates relative to, so that a scene far from the
// origin keeps the precision of its own size.

#include <glm/vec3.hpp>

#include "shadowgen/model/scene.h"

namespace shadowgen {

// The midpoint of the box around every face's outer loops (holes lie inside them); the
// origin for a scene without vertices.
glm::dvec3 scene_centre(const Scene& scene);

}  // namespace shadowgen
