#pragma once

// What every face sees of the sky (docs/sky.md, "Sky view factor"): per face and patch,
// the patch's projected solid angle from the face (patch_cosine.h) weighted by the face's
// exact lit fraction under the patch's light (sky_lights.h), summed over the face's parts:
//
//   lit_weight[f][p] = Σ over parts i of f: lit area(i, p) × I(n_i, p) / area(f)
//
// in steradians, so that the sky view factor is (1/π) Σ_p lit_weight[f][p] and a sky of
// radiance L_p gives the irradiance Σ_p lit_weight[f][p] L_p. A part that faces away from a
// patch's centre but sees part of the patch (a patch its plane cuts) has no lit area under
// the patch's light; it counts that sliver, which lies along its own horizon, as
// unobstructed (lit fraction 1), so that an unobstructed face gets the closed forms.

#include <cstddef>
#include <functional>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/sky/sky_patches.h"

namespace shadowgen::sky {

// The Reinhart subdivision taken where none is asked for (--sky): the least whose sky view
// factors meet the accuracy docs/sky.md states (bench/RESULTS.md, the convergence table).
inline constexpr int kDefaultSubdivisions = 8;

struct SkyOptions {
  int subdivisions = kDefaultSubdivisions;  // Reinhart MF:N; 1 is Tregenza's
  unsigned threads = 0;                     // GenerateOptions::threads
  // GenerateOptions::on_light_done: light k is patch k.
  std::function<void(std::size_t patch, const LightStats&)> on_light_done;
};

struct SkyExposure {
  std::vector<SkyPatch> patches;
  std::vector<double> area;                      // [face]
  std::vector<std::vector<double>> lit_weight;   // [face][patch], steradians, as above
  std::vector<std::vector<double>> open_weight;  // [face][patch]: the same, nothing shading
  // [face]: the face's view of the ground, (1 - n_z)/2 of each part's unit normal n
  // weighted by area: the lower hemisphere seen through the face's plane, unobstructed.
  std::vector<double> ground_view_factor;
};

// Throws what generate_shadows throws (GenerationError); std::invalid_argument for
// subdivisions outside reinhart_patches's range.
SkyExposure sky_exposure(const Scene& scene, const SkyOptions& options = {});

// (1/π) Σ_p lit_weight[face][p]: the isotropic sky's view factor with exact obstruction.
double sky_view_factor(const SkyExposure& exposure, std::size_t face);

}  // namespace shadowgen::sky
