#include "shadowgen/pipeline/light_choice.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/model/keep_marked.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen {
namespace {

// An instant of a sun path chosen without the rest of its path: a light of its own, as a
// `sun` entry with its id and its `time` would place it, so that nothing takes the one
// instant for the path (its sun hours, its shading schedule).
void own_light(Light& light) {
  light.sun->sun_id = light.id;
  light.sun->step_min = 0;
  light.sun->path_from.clear();
  light.sun->path_to.clear();
}

// Whether each of the scene's lights is kept; `named_paths` gets the sun paths named by
// their id (Scene::sun_paths).
std::vector<bool> chosen(const Scene& scene, std::span<const std::string> ids,
                         const std::string& file, std::set<std::string>& named_paths) {
  std::vector<bool> keep(scene.lights.size(), false);
  for (const std::string& id : ids) {
    const auto named = [&id](const Light& light) {
      return light.id == id || (light.sun && light.sun->sun_id == id);
    };
    bool found = false;
    for (const SunPathSpan& path : scene.sun_paths) {
      if (path.id != id) continue;
      named_paths.insert(id);
      found = true;
    }
    for (std::size_t k = 0; k < scene.lights.size(); ++k) {
      if (!named(scene.lights[k])) continue;
      keep[k] = true;
      found = true;
    }
    if (!found) {
      std::string known;
      const auto add = [&known](const std::string& name) {
        known += (known.empty() ? "" : ", ") + std::string("'") + one_line(name) + "'";
      };
      for (const Light& light : scene.lights) add(light.id);
      for (const SunPathSpan& path : scene.sun_paths) {
        const bool placed = std::any_of(
            scene.lights.begin(), scene.lights.end(),
            [&path](const Light& l) { return in_sun_path(l) && l.sun->sun_id == path.id; });
        if (!placed) add(path.id);  // a path without an instant
      }
      throw InputError(file, "",
                       "--lights names '" + one_line(id) + "', which is not a light of it (" +
                           (known.empty() ? std::string("it has none") : "its lights: " + known) +
                           ")");
    }
  }
  return keep;
}

// Keeps the sun paths of `scene` whose instants are all kept (`keep`, per light) and, of
// those without an instant, the ones named; the instants kept of any other path become
// lights of their own (own_light).
void keep_paths(Scene& scene, const std::vector<bool>& keep,
                const std::set<std::string>& named_paths) {
  std::map<std::string, std::pair<std::size_t, std::size_t>> counts;  // id: instants, kept
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    if (!in_sun_path(scene.lights[l])) continue;
    auto& [instants, kept] = counts[scene.lights[l].sun->sun_id];
    ++instants;
    kept += keep[l] ? 1 : 0;
  }
  const auto whole = [&](const std::string& id) {
    const auto at = counts.find(id);
    return at == counts.end() ? named_paths.contains(id) : at->second.first == at->second.second;
  };
  std::vector<bool> own(scene.lights.size(), false);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    own[l] = keep[l] && in_sun_path(scene.lights[l]) && !whole(scene.lights[l].sun->sun_id);
  }
  std::erase_if(scene.sun_paths, [&whole](const SunPathSpan& path) { return !whole(path.id); });
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    if (own[l]) own_light(scene.lights[l]);
  }
}

}  // namespace

void keep_lights(Scene& scene, std::span<const std::string> ids, const std::string& file) {
  if (ids.empty()) return;
  std::set<std::string> named_paths;
  const std::vector<bool> keep = chosen(scene, ids, file, named_paths);
  keep_paths(scene, keep, named_paths);
  keep_marked(scene.lights, keep);
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
// whose instants are kept (their indices renumbered); of the paths without an instant,
// those `named_paths` has, or every one where it is null. A path's sums cover all its
// instants: one whose lit polygons were dropped cannot lose some of them; the instants
// kept of one that kept them become lights of their own (own_light).
void keep_marked(ShadowedScene& shadowed, const std::vector<bool>& keep, const std::string& file,
                 const std::set<std::string>* named_paths) {
  std::vector<std::size_t> renumbered(keep.size());
  for (std::size_t l = 0, next = 0; l < keep.size(); ++l) renumbered[l] = keep[l] ? next++ : 0;
  std::vector<SunPathHours> paths;
  std::set<std::string> kept_ids;
  std::vector<std::size_t> own;  // the kept instants of paths not kept whole
  for (SunPathHours& path : shadowed.sun_paths) {
    const auto kept = static_cast<std::size_t>(
        std::count_if(path.instants.begin(), path.instants.end(),
                      [&keep](std::size_t l) { return static_cast<bool>(keep[l]); }));
    const bool whole = path.instants.empty()
                           ? named_paths == nullptr || named_paths->contains(path.id)
                           : kept == path.instants.size();
    if (whole) {
      for (std::size_t& l : path.instants) l = renumbered[l];
      kept_ids.insert(path.id);
      paths.push_back(std::move(path));
    } else if (kept > 0 && !path.lit_polygons_kept) {
      throw InputError(file, "",
                       "--lights names " + std::to_string(kept) + " of the " +
                           std::to_string(path.instants.size()) + " instants of sun path '" +
                           one_line(path.id) +
                           "', whose lit polygons were summed into sun hours: name the path "
                           "itself, or generate with --keep-instants");
    } else {
      for (const std::size_t l : path.instants) {
        if (keep[l]) own.push_back(l);
      }
    }
  }
  shadowed.sun_paths = std::move(paths);
  shadowed.edit_scene([&](Scene& scene) {
    for (const std::size_t l : own) own_light(scene.lights[l]);
    std::erase_if(scene.sun_paths,
                  [&kept_ids](const SunPathSpan& path) { return !kept_ids.contains(path.id); });
  });
  shadowed.keep_lights(keep);
}

}  // namespace

void keep_lights(ShadowedScene& shadowed, std::span<const std::string> ids,
                 const std::string& file) {
  if (ids.empty()) return;
  std::set<std::string> named_paths;
  const std::vector<bool> keep = chosen(shadowed.scene(), ids, file, named_paths);
  keep_marked(shadowed, keep, file, &named_paths);
}

std::vector<std::string> drop_summed_instants(ShadowedScene& shadowed, const std::string& file) {
  const LitAreas areas(shadowed);
  std::vector<bool> keep(shadowed.scene().lights.size());
  std::vector<std::string> dropped;
  for (std::size_t l = 0; l < keep.size(); ++l) {
    const SunPathHours* path = areas.summed_path(l);
    keep[l] = path == nullptr;
    if (path && (dropped.empty() || dropped.back() != path->id)) dropped.push_back(path->id);
  }
  keep_marked(shadowed, keep, file, nullptr);
  return dropped;
}

}  // namespace shadowgen
