#pragma once

// The paper's first "shadow matrix": the views through which a light sees the scene.

#include <span>
#include <vector>

#include "hsr/polygon3.h"
#include "hsr/view.h"
#include "shadowgen/model/scene.h"

namespace shadowgen {

// Directional light: one orthographic view along its direction, centred on `centre`.
// Point light: the 90-degree frusta along ±x, ±y, ±z around it that contain part of some
// polygon, with a near distance below the distance to every polygon not in a plane
// through the light, so nothing of the scene is cut off at the near plane (a point of a
// frustum at distance r from the light has depth at least r/√3) where the light keeps to
// the supported range of depths (shadowgen/model/coordinate_range.h, lamp_near_distance;
// the scene reader refuses a light that does not).
std::vector<hsr::View> light_views(const Light& light, std::span<const hsr::Polygon3> polygons,
                                   std::span<const hsr::Plane3> planes, const glm::dvec3& centre);

}  // namespace shadowgen
