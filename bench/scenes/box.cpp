#include "bench/scenes/box.h"

#include <cmath>
#include <numbers>

namespace shadowgen::bench {

std::vector<hsr::Polygon3> box_faces(const glm::dvec3& lo, const glm::dvec3& hi, bool floor) {
  const double x0 = lo.x, y0 = lo.y, z0 = lo.z, x1 = hi.x, y1 = hi.y, z1 = hi.z;
  std::vector<hsr::Polygon3> faces = {
      {{{x0, y0, z0}, {x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}}, {}},  // -x
      {{{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, {}},  // +x
      {{{x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}}, {}},  // -y
      {{{x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}}, {}},  // +y
      {{{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}, {}},  // +z
  };
  if (floor) faces.push_back({{{x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}}, {}});
  return faces;
}

void add_box(Scene& scene, const std::string& id, const glm::dvec3& lo, const glm::dvec3& hi,
             bool floor) {
  int k = 0;
  for (hsr::Polygon3& p : box_faces(lo, hi, floor)) {
    scene.faces.push_back({id + "/" + std::to_string(k++), {std::move(p)}, ""});
  }
}

Light sun_at(double elevation_deg, double azimuth_deg) {
  const double elevation = elevation_deg * std::numbers::pi / 180.0;
  const double azimuth = azimuth_deg * std::numbers::pi / 180.0;
  Light sun;
  sun.id = "sun";
  sun.type = LightType::kDirectional;
  sun.direction = {-std::cos(elevation) * std::cos(azimuth),
                   -std::cos(elevation) * std::sin(azimuth), -std::sin(elevation)};
  return sun;
}

}  // namespace shadowgen::bench
