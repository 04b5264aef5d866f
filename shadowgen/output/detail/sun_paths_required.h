#pragma once

// Reports over sun paths (sun hours, irradiation, shading schedules) refuse an input
// without one in the same words.

#include <string>
#include <string_view>

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::output::detail {

// InputError naming the input (Scene::file) when `shadowed` has no sun path; `what` says what
// the report would have given ("sun hours").
void require_sun_paths(const ShadowedScene& shadowed, std::string_view what);

}  // namespace shadowgen::output::detail
