#include "shadowgen/sky/sky_lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace shadowgen::sky {
namespace {

// Scaled by a power of two, which is exact, so that the largest component lies in
// [0.5, 1), as the scene reader leaves every directional light (Light::direction).
glm::dvec3 light_direction(const glm::dvec3& v) {
  int exponent = 0;
  std::frexp(std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}), &exponent);
  return {std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent)};
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace

Scene sky_scene(const Scene& scene, std::span<const SkyPatch> patches) {
  Scene sky = scene;
  sky.lights.clear();
  sky.sun_paths.clear();
  const double north_axis_deg = scene.site ? scene.site->north_axis_deg : 0.0;
  const std::string path(kSkyPathId);
  sky.sun_paths.push_back({path, 60, "", ""});
  sky.lights.reserve(patches.size());
  for (std::size_t k = 0; k < patches.size(); ++k) {
    const SkyPatch& patch = patches[k];
    Light light;
    light.id = path + "@" + std::to_string(k + 1);
    light.type = LightType::kDirectional;
    light.direction = light_direction(-scene_from_sky(patch.centre, north_axis_deg));
    SunInstant instant;
    instant.sun_id = path;
    instant.step_min = 60;
    instant.azimuth_deg = degrees(std::atan2(patch.centre.x, patch.centre.y));
    instant.elevation_deg = degrees(std::asin(patch.centre.z));
    light.sun = instant;
    sky.lights.push_back(std::move(light));
  }
  return sky;
}

}  // namespace shadowgen::sky
