#include "detail/scene_regions.h"

namespace shadowgen::output::detail {

SceneRegions scene_regions(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene();
  SceneRegions regions;
  regions.of_face.resize(scene.faces.size());
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    regions.of_face[f] = light_regions(shadowed, f);
    for (const LightRegion& r : regions.of_face[f]) regions.sets.insert(r.lights);
  }
  return regions;
}

LightSetNames light_set_names(const Scene& scene, const LightSets& sets,
                              std::string (*format_name)(std::string_view)) {
  LightSetNames names;
  std::set<std::string> taken;
  for (const LightSet& s : sets) {
    const std::string base = format_name(light_set_name(scene, s));
    std::string name = base;
    for (int k = 2; taken.count(name) != 0; ++k) name = base + "~" + std::to_string(k);
    taken.insert(name);
    names.emplace(s, name);
  }
  return names;
}

}  // namespace shadowgen::output::detail
