#include "shadowgen/pipeline/light_choice.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen {
namespace {

// Whether each of the scene's lights is kept.
std::vector<bool> chosen(const Scene& scene, std::span<const std::string> ids,
                         const std::string& file) {
  std::vector<bool> keep(scene.lights.size(), false);
  for (const std::string& id : ids) {
    const auto named = [&id](const Light& light) {
      return light.id == id || (light.sun && light.sun->sun_id == id);
    };
    bool found = false;
    for (std::size_t k = 0; k < scene.lights.size(); ++k) {
      if (!named(scene.lights[k])) continue;
      keep[k] = true;
      found = true;
    }
    if (!found) {
      std::string known;
      for (const Light& light : scene.lights) {
        known += (known.empty() ? "" : ", ") + std::string("'") + one_line(light.id) + "'";
      }
      throw InputError(file, "",
                       "--lights names '" + one_line(id) + "', which is not a light of it (" +
                           (known.empty() ? std::string("it has none") : "its lights: " + known) +
                           ")");
    }
  }
  return keep;
}

template <class T>
void keep_marked(std::vector<T>& items, const std::vector<bool>& keep) {
  std::vector<T> kept;
  kept.reserve(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (keep[k]) kept.push_back(std::move(items[k]));
  }
  items = std::move(kept);
}

}  // namespace

void keep_lights(Scene& scene, std::span<const std::string> ids, const std::string& file) {
  if (ids.empty()) return;
  keep_marked(scene.lights, chosen(scene, ids, file));
}

void keep_lights(ShadowedScene& shadowed, std::span<const std::string> ids,
                 const std::string& file) {
  if (ids.empty()) return;
  const std::vector<bool> keep = chosen(shadowed.scene, ids, file);
  for (const std::vector<std::vector<LitPolygon>>& per_light : shadowed.lit) {
    if (per_light.size() != keep.size()) {
      throw std::invalid_argument("keep_lights: lit polygons not shaped [face][light]");
    }
  }
  keep_marked(shadowed.scene.lights, keep);
  for (std::vector<std::vector<LitPolygon>>& per_light : shadowed.lit) keep_marked(per_light, keep);
}

}  // namespace shadowgen
