#pragma once

// EnergyPlus's diffuse sky shading ratios per surface (docs/sky.md, "EnergyPlus's diffuse
// shading ratio"; sky/energyplus_sky.h), as CSV:
//
//   surface_name,dif_shdg_ratio_iso_sky,dif_shdg_ratio_horiz[,sky_shading_ratio]
//   ROOF,1,1
//   WALL-SOUTH,0.48214285714285715,0.11
//
// one row per face in scene order, named as the shading schedule names its columns (the
// EnergyPlus surface name, upper case); the ratios as the report CSV writes numbers;
// sky_shading_ratio, the ratio over a fine subdivision's patches, where the shading holds it.

#include <string>

#include "shadowgen/model/scene.h"
#include "shadowgen/sky/energyplus_sky.h"

namespace shadowgen {

// `shading` is `scene`'s. InputError (Scene::file, the face) for a face whose id cannot be
// an EnergyPlus surface name, as energyplus_shading refuses it.
std::string energyplus_sky_csv(const Scene& scene, const sky::EnergyPlusSkyShading& shading);

// The same InputError, before any shadow is computed.
void require_energyplus_surface_names(const Scene& scene);

}  // namespace shadowgen
