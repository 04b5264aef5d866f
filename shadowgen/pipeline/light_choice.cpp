#include "shadowgen/pipeline/light_choice.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
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

std::vector<std::string> keep_spread_instants(Scene& scene, std::size_t per_path) {
  std::vector<bool> keep(scene.lights.size(), true);
  std::vector<std::string> kept;
  // A path's instants stand together, in time order (scene.h): one run per `sun` entry.
  for (std::size_t first = 0; first < scene.lights.size();) {
    if (!in_sun_path(scene.lights[first])) {
      ++first;
      continue;
    }
    std::size_t end = first + 1;
    while (end < scene.lights.size() && in_sun_path(scene.lights[end]) &&
           scene.lights[end].sun->sun_id == scene.lights[first].sun->sun_id) {
      ++end;
    }
    const std::size_t n = end - first;
    std::vector<bool> spread(n, n <= per_path);
    for (std::size_t i = 0; n > per_path && i < per_path; ++i) {
      spread[(2 * i + 1) * n / (2 * per_path)] = true;
    }
    for (std::size_t k = 0; k < n; ++k) {
      keep[first + k] = spread[k];
      if (spread[k]) kept.push_back(scene.lights[first + k].id);
    }
    first = end;
  }
  keep_marked(scene.lights, keep);
  return kept;
}

namespace {

// Keeps the marked lights of a database with their lit polygons, and the sun paths all of
// whose instants are kept (their indices renumbered). A path's sums cover all its instants:
// one whose lit polygons were dropped cannot lose some of them; one that kept them becomes
// plain lights.
void keep_marked(ShadowedScene& shadowed, const std::vector<bool>& keep, const std::string& file) {
  if (shadowed.lit.lights() != keep.size()) {
    throw std::invalid_argument("keep_lights: lit polygons for " +
                                std::to_string(shadowed.lit.lights()) + " lights, " +
                                std::to_string(keep.size()) + " chosen or not");
  }
  std::vector<std::size_t> renumbered(keep.size());
  for (std::size_t l = 0, next = 0; l < keep.size(); ++l) renumbered[l] = keep[l] ? next++ : 0;
  std::vector<SunPathHours> paths;
  for (SunPathHours& path : shadowed.sun_paths) {
    const auto kept = static_cast<std::size_t>(
        std::count_if(path.instants.begin(), path.instants.end(),
                      [&keep](std::size_t l) { return static_cast<bool>(keep[l]); }));
    if (kept == path.instants.size()) {
      for (std::size_t& l : path.instants) l = renumbered[l];
      paths.push_back(std::move(path));
    } else if (kept > 0 && !path.lit_polygons_kept) {
      throw InputError(file, "",
                       "--lights names " + std::to_string(kept) + " of the " +
                           std::to_string(path.instants.size()) + " instants of sun path '" +
                           one_line(path.id) +
                           "', whose lit polygons were summed into sun hours: name the path "
                           "itself, or generate with --keep-instants");
    }
  }
  shadowed.sun_paths = std::move(paths);
  keep_marked(shadowed.scene.lights, keep);
  shadowed.lit.keep_lights(keep);
  if (!shadowed.estimated_lit_area.empty()) keep_marked(shadowed.estimated_lit_area, keep);
}

}  // namespace

void keep_lights(ShadowedScene& shadowed, std::span<const std::string> ids,
                 const std::string& file) {
  if (ids.empty()) return;
  keep_marked(shadowed, chosen(shadowed.scene, ids, file), file);
}

std::vector<std::string> drop_summed_instants(ShadowedScene& shadowed, const std::string& file) {
  const LitAreas areas(shadowed);
  std::vector<bool> keep(shadowed.scene.lights.size());
  std::vector<std::string> dropped;
  for (std::size_t l = 0; l < keep.size(); ++l) {
    const SunPathHours* path = areas.summed_path(l);
    keep[l] = path == nullptr;
    if (path && (dropped.empty() || dropped.back() != path->id)) dropped.push_back(path->id);
  }
  keep_marked(shadowed, keep, file);
  return dropped;
}

}  // namespace shadowgen
