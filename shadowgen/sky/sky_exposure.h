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
#include <glm/vec3.hpp>
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

// How far in front of a part's plane (the sine of the angle) a patch's centre must lie for
// the part's lit area under the patch's light to count: a centre within it, in the plane
// but for rounding, may have lit the part or not; the part then counts as unobstructed.
inline constexpr double kCentreInFrontOfPlane = 1e-9;

// A face's part as the sky sees it: its area, and its unit front normal in east-north-up
// axes (its Newell vector, turned from the scene's axes by the site's north_axis_deg);
// `oriented` false for a part without area or normal, which sees no sky.
struct SkyPart {
  double area = 0.0;
  glm::dvec3 normal{0.0};
  bool oriented = false;
};

// `face`'s parts in order; `north_axis_deg` as Site::north_axis_deg (0 without a site).
std::vector<SkyPart> sky_parts(const Face& face, double north_axis_deg);

// The lit area of part `i` of face `f` under instant `k` of the sky's `path`, a light from
// `centre`: the part's whole area where the centre lies within kCentreInFrontOfPlane of its
// plane (or behind it), and never more than the part's area.
double sky_lit_area(const SunPathHours& path, std::size_t f, std::size_t i, const SkyPart& part,
                    std::size_t k, const glm::dvec3& centre);

// Throws what generate_shadows throws (GenerationError); std::invalid_argument for
// subdivisions outside reinhart_patches's range.
SkyExposure sky_exposure(const Scene& scene, const SkyOptions& options = {});

// The lights of `patches` (sky_scene) generated as generate --areas-only generates a sun
// path, on options.threads with options.on_light_done: instant k of the path is patch k.
SunPathHours sky_lit_areas(const Scene& scene, const std::vector<SkyPatch>& patches,
                           const SkyOptions& options);

// The exposure to `patches` of `scene`'s faces, from a path `lit` whose instants from
// `first` on are their lights, in order.
SkyExposure sky_exposure_of(const Scene& scene, const SunPathHours& lit, std::size_t first,
                            std::vector<SkyPatch> patches);

// (1/π) Σ_p lit_weight[face][p]: the isotropic sky's view factor with exact obstruction.
double sky_view_factor(const SkyExposure& exposure, std::size_t face);

}  // namespace shadowgen::sky
