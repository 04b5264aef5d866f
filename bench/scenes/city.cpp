#include "bench/scenes/city.h"

#include <cmath>
#include <numbers>
#include <string>

#include "bench/scenes/box.h"
#include "bench/scenes/random.h"

namespace shadowgen::bench {

Scene city_scene(const CitySpec& spec) {
  Scene scene;
  SceneRandom random(spec.seed);
  const int n = spec.lots_per_side;
  const double lot = spec.lot;
  scene.faces.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * 6);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x0 = i * lot, y0 = j * lot;
      const std::string lot_id = "lot" + std::to_string(i) + "_" + std::to_string(j);
      scene.faces.push_back(
          {lot_id + "/ground",
           {hsr::Polygon3{
               {{x0, y0, 0.0}, {x0 + lot, y0, 0.0}, {x0 + lot, y0 + lot, 0.0}, {x0, y0 + lot, 0.0}},
               {}}},
           ""});
      const double w = lot * random.uniform(0.4, 0.8);
      const double d = lot * random.uniform(0.4, 0.8);
      const double bx = x0 + random.uniform(0.0, lot - w);
      const double by = y0 + random.uniform(0.0, lot - d);
      const double h = random.log_uniform(6.0, 60.0);
      add_box(scene, lot_id + "/building", {bx, by, 0.0}, {bx + w, by + d, h}, false);
    }
  }

  scene.lights.push_back(sun_at(40, 30));

  Light lamp;
  lamp.id = "lamp";
  lamp.type = LightType::kPoint;
  const double corner = std::round(0.5 * n) * lot;
  lamp.position = {corner, corner, 6.0};
  lamp.range = LightRange{0.5 * lot, 4.0 * lot, 2.0};
  scene.lights.push_back(lamp);
  return scene;
}

int city_lots_for_faces(std::size_t faces) {
  return static_cast<int>(std::lround(std::sqrt(static_cast<double>(faces) / 6.0)));
}

}  // namespace shadowgen::bench
