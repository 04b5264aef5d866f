#pragma once

// The EnergyPlus surface names of a scene's faces, as the shading schedule's columns and the
// sky's shading ratios name them: the surface's Name for a face read from an EnergyPlus
// model (FaceOrigin::object, without the scene entry's id), the face's id otherwise; upper
// case, as EnergyPlus keeps names.

#include <string>
#include <vector>

#include "shadowgen/model/scene.h"

namespace shadowgen::output::detail {

// [face] in scene order. InputError naming the input (Scene::file) and the face for a name
// that cannot be an EnergyPlus surface name (empty, a comma or a control character in it,
// spaces around it) or that is another face's in upper case.
std::vector<std::string> energyplus_surface_names(const Scene& scene);

}  // namespace shadowgen::output::detail
