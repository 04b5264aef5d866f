#pragma once

// Axis-aligned boxes as scene faces, each face a rectangle whose outer loop runs
// counter-clockwise seen from outside (normals outward).

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

// The faces of the box [lo, hi]: -x, +x, -y, +y, +z and, with `floor`, -z.
std::vector<hsr::Polygon3> box_faces(const glm::dvec3& lo, const glm::dvec3& hi, bool floor);

// Appends the box's faces to the scene with ids "<id>/0", "<id>/1", ...
void add_box(Scene& scene, const std::string& id, const glm::dvec3& lo, const glm::dvec3& hi,
             bool floor);

// A directional light called "sun", `elevation_deg` above the horizon, coming from the
// azimuth `azimuth_deg` (counter-clockwise from +x).
Light sun_at(double elevation_deg, double azimuth_deg);

}  // namespace shadowgen::bench
