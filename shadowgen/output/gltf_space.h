#pragma once

// Where glTF 2.0 differs from the scene in space and colour, in one home for every glTF
// writer (gltf_export.h, the viewer's model): glTF's +y is up where the scene's +z is,
// and its colour factors are linear where the project's colours are sRGB.

#include <glm/vec3.hpp>

namespace shadowgen {

// The scene's point p, or direction, in glTF's axes: (x, z, −y), a rotation (the inverse
// of the glTF reader's (x, y, z) → (x, −z, y)).
glm::dvec3 gltf_axes(const glm::dvec3& p);

// An sRGB channel in [0, 1] as the linear value glTF's colour factors hold (the sRGB
// transfer function, IEC 61966-2-1).
double linear_from_srgb(double c);

}  // namespace shadowgen
