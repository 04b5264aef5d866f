#pragma once

// EnergyPlus's shading of isotropic sky diffuse light (docs/sky.md, "EnergyPlus's diffuse
// shading ratio"), computed as EnergyPlus's SkyDifSolarShading computes it but from exact
// lit fractions: the sky sampled in NPhi = 6 altitudes (7.5°, 22.5°, ..., 82.5°) by
// NTheta = 24 azimuths (0°, 15°, ..., 345° counterclockwise from east), 144 directions d
// each weighted for a face of unit outward normal n by
//
//   w(d, n) = cos φ Δθ Δφ (n·d)    where n·d >= 0 (skipped otherwise), Δθ = Δφ = 15°,
//
// and, with F(d) the face's sunlit fraction under a directional light from d,
//
//   DifShdgRatioIsoSky = Σ_d F(d) w(d, n) / Σ_d w(d, n)
//   DifShdgRatioHoriz  = the same over the lowest altitude (7.5°) alone,
//
// 0 where the face sees none of the directions (EnergyPlus divides by 0 + Eps there). A
// face of several parts sums its parts' terms, each weighted by its share of the face's
// area. A part that a direction reaches within kCentreInFrontOfPlane of its plane counts as
// lit by it (its weight is below 1e-9 Δθ Δφ), so that an unobstructed face gets 1 exactly.
//
// Beside it, where asked, the same ratio over a fine subdivision's patches and their exact
// cosine integrals: Σ_p lit_weight / Σ_p open_weight of sky_exposure.h.

#include <cstddef>
#include <optional>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/sky/sky_exposure.h"
#include "shadowgen/sky/sky_patches.h"

namespace shadowgen::sky {

inline constexpr int kEnergyPlusAltitudes = 6;  // EnergyPlus's NPhi
inline constexpr int kEnergyPlusAzimuths = 24;  // EnergyPlus's NTheta

// EnergyPlus's 144 sky directions as patches centred on them (altitude rows from the horizon
// up, in each row θ = 0°, 15°, ... counterclockwise from east, as EnergyPlus loops), each
// spanning 15° by 15° around its direction.
std::vector<SkyPatch> energyplus_sky_patches();

// EnergyPlus's weight cos φ Δθ Δφ (n·d) of `patch` (one of energyplus_sky_patches) for a
// face of unit normal n in east-north-up axes; 0 where n·d < 0.
double energyplus_sky_weight(const SkyPatch& patch, const glm::dvec3& normal);

struct EnergyPlusSkyShading {
  // [face], EnergyPlus's WithShdgIsoSky, WoShdgIsoSky, WithShdgHoriz, WoShdgHoriz.
  std::vector<double> with_iso_sky, without_iso_sky, with_horizon, without_horizon;
  // The subdivision's exposure, where asked (`fine`).
  std::optional<SkyExposure> fine;
};

// All of the sky's lights in one path: EnergyPlus's 144 directions first, then, with
// `fine`, the patches of Reinhart's MF:options.subdivisions; options.on_light_done counts
// them in that order. Throws what sky_exposure throws.
EnergyPlusSkyShading energyplus_sky_shading(const Scene& scene, const SkyOptions& options,
                                            bool fine);

// The patches energyplus_sky_shading lights, in its order (for sky_scene).
std::vector<SkyPatch> energyplus_sky_lights(const SkyOptions& options, bool fine);

// with / without, 0 where without is 0.
double shading_ratio(double with, double without);

// Σ_p lit_weight / Σ_p open_weight of `face`: the ratio over the subdivision's patches.
double fine_shading_ratio(const SkyExposure& exposure, std::size_t face);

}  // namespace shadowgen::sky
