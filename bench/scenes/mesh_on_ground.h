#pragma once

// Benchmark scene: a real mesh file standing just above a square ground, lit by a sun and
// a lamp. The mesh is read by shadowgen's own scene reader (a scene that references the
// file, docs/scene-format.md), turned so that its `up` axis is +z, scaled to a largest
// extent of 1, centred over the origin, and lifted so that its lowest point is 0.02 above
// the ground: the shadows fall on the ground and on the mesh itself, and no face lies on
// the ground (contact is not what is measured). The ground is one square face of side
// 4 on z = 0, centred at the origin. Lights: "sun", directional, (-0.5, 0.35, -1)
// (elevation about 56°); "lamp", a point light at (0.7, -0.55, 1.2), just above and
// beside the mesh, without a range, so its shadows are strongly perspective. Faces: the
// ground first, then the mesh's faces in file order.

#include <filesystem>

#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

enum class UpAxis { kY, kZ };

Scene mesh_on_ground(const std::filesystem::path& mesh, UpAxis up);

}  // namespace shadowgen::bench
