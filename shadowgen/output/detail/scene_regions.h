#pragma once

// Every face split by the set of lights reaching it (shadowgen/shadows/light_regions.h),
// and the sets that occur, named: what the OBJ export (obj_export.h) and the glTF export
// (gltf_export.h) write, one material per set.

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/shadows/light_regions.h"

namespace shadowgen::output::detail {

using LightSet = std::vector<std::size_t>;
using LightSets = std::set<LightSet, LightSetLess>;
using LightSetNames = std::map<LightSet, std::string, LightSetLess>;

struct SceneRegions {
  std::vector<std::vector<LightRegion>> of_face;  // light_regions() of each face
  LightSets sets;                                 // every set some region has
};

// The light regions of every face; throws what light_regions throws.
SceneRegions scene_regions(const ShadowedScene& shadowed);

// One name per set, all distinct: `format_name` of light_set_name() ("sun+lamp",
// "shadow"), "~2", "~3", ... appended to a name a set before it (in LightSetLess order)
// already has.
LightSetNames light_set_names(const Scene& scene, const LightSets& sets,
                              std::string (*format_name)(std::string_view));

}  // namespace shadowgen::output::detail
