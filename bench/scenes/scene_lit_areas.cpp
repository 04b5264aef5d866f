#include "bench/scenes/scene_lit_areas.h"

#include <stdexcept>
#include <string>

#include "hsr/area.h"

namespace shadowgen::bench {

LitAreas checked_lit_areas(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene();
  LitAreas out;
  out.face_area.resize(scene.faces.size());
  out.lit.assign(scene.lights.size(), std::vector<double>(scene.faces.size(), 0.0));
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    out.face_area[f] = hsr::area(scene.faces[f].parts);
    out.total_area += out.face_area[f];
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const double lit = lit_area(shadowed.lit()[f][l]);
      if (!(lit >= 0.0 && lit <= out.face_area[f] * (1.0 + 1e-9))) {
        throw std::runtime_error("face " + scene.faces[f].id + ", light " + scene.lights[l].id +
                                 ": lit area " + std::to_string(lit) + " outside [0, " +
                                 std::to_string(out.face_area[f]) + "]");
      }
      out.lit[l][f] = lit;
    }
  }
  return out;
}

}  // namespace shadowgen::bench
