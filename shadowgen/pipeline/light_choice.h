#pragma once

// A run limited to some of the input's lights (the command line's --lights): only those
// are generated, reported, exported or drawn, as if the input held no other. Work and
// output then grow with the lights chosen, not with all of the input's.

#include <span>
#include <string>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

// Keeps the lights whose ids are in `ids`, in the input's order whatever order they are
// named in (a name given twice counts once). The id of a `sun` entry names all its
// instants (Light::sun), in a scene and in a database, and a sun path without an instant
// (Scene::sun_paths) is kept where its id is named. Instants named without the rest of
// their path become lights of their own, as a `sun` entry with their id and `time` would
// place them (SunInstant::sun_id their id, step_min 0): the path is not kept, so that no
// output takes them for it. Throws InputError naming `file` for an id the input has no
// light of, listing the ones it has. An empty `ids` keeps every light.
void keep_lights(Scene& scene, std::span<const std::string> ids, const std::string& file);

// Keeps every light of `scene` but the instants of its sun paths, and of each path
// `per_path` instants spread evenly over it, every one where it has no more: of its n
// instants (those with the sun up, in time order), the ranks ⌊(i + ½)·n / per_path⌋ for
// i < per_path. Returns the ids of the instants kept, in the scene's order. What a
// comparison of view methods draws (`compare --view`): drawing every instant of a year
// pixel by pixel costs thousands of pictures.
std::vector<std::string> keep_spread_instants(Scene& scene, std::size_t per_path);

// The same for a shadowed database: its lights and their lit polygons (std::invalid_argument
// when `lit` is not shaped [face][light]), and the sun paths whose instants are all kept
// (a path's id names them all), as for a scene. Naming only some instants of a path whose
// lit polygons were summed away is an InputError: its sums cannot be split.
void keep_lights(ShadowedScene& shadowed, std::span<const std::string> ids,
                 const std::string& file);

// Drops the instants of sun paths that kept only their lit areas, with those paths, for
// what draws lit polygons (export, render); returns the ids of the paths dropped.
std::vector<std::string> drop_summed_instants(ShadowedScene& shadowed, const std::string& file);

}  // namespace shadowgen
