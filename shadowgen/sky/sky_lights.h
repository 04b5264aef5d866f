#pragma once

// A scene's sky as lights (docs/sky.md, "Sky view factor"): each patch a directional light
// from its centre, all of them the instants of one path, kSkyPathId, so that the
// areas-only sun-path step (shadows/generate.h with sun_hours_regions off) gives every
// face's exact lit area per patch, with the threads, progress and speed-ups a sun path
// gets.

#include <span>
#include <string_view>

#include "shadowgen/model/scene.h"
#include "shadowgen/sky/sky_patches.h"

namespace shadowgen::sky {

inline constexpr std::string_view kSkyPathId = "sky";

// `scene`'s faces (and site, views, groups) with its lights and sun paths replaced by one
// light per patch, in the patches' order, named `sky@K` (K from 1) and travelling from the
// patch's centre, turned into the scene's axes by the site's north_axis_deg (0 without a
// site). Each light is an instant of the path kSkyPathId (Light::sun, step_min 60, no time).
Scene sky_scene(const Scene& scene, std::span<const SkyPatch> patches);

}  // namespace shadowgen::sky
