#include "street_canyon.h"

#include <cmath>
#include <string>
#include <utility>

namespace shadowgen::bench {
namespace {

Face quad(std::string id, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
  Face face;
  face.id = std::move(id);
  face.parts.push_back({{a, b, c, d}, {}});
  return face;
}

}  // namespace

Scene street_canyon(double height) {
  Scene scene;
  scene.file = "street canyon";
  const double h = 0.005, l = 100.0;
  scene.faces.push_back(quad("floor", {-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}));
  scene.faces.push_back(
      quad("south", {-l, -0.5, 0}, {l, -0.5, 0}, {l, -0.5, height}, {-l, -0.5, height}));
  scene.faces.push_back(
      quad("north", {l, 0.5, 0}, {-l, 0.5, 0}, {-l, 0.5, height}, {l, 0.5, height}));
  return scene;
}

double street_canyon_sky_view_factor(double height) { return std::cos(std::atan(2.0 * height)); }

}  // namespace shadowgen::bench
