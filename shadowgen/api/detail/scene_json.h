#pragma once

// A scene held in memory (shadowgen/api/scene_data.h) as the scene file that means the
// same (docs/scene-format.md), so that make_scene checks it by the scene reader's own rules
// and messages.

#include <string>

#include "shadowgen/api/scene_data.h"

namespace shadowgen::api::detail {

// The scene file's text. Throws InputError naming data.name (and the face) for a number
// that is not finite, which JSON cannot hold.
std::string scene_json(const SceneData& data);

}  // namespace shadowgen::api::detail
