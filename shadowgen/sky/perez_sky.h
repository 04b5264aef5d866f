#pragma once

// The Perez all-weather sky (docs/sky.md, "Perez diffuse sky"): an hour's diffuse
// horizontal irradiance spread over the sky's patches as the sky's luminance distribution
// of R. Perez, R. Seals and J. Michalsky, "All-weather model for sky luminance distribution
// - preliminary configuration and validation", Solar Energy 50(3), 1993, 235-245 (and its
// erratum, Solar Energy 51(5), 1993, 423), driven by the sky's clearness ε and brightness Δ
// of R. Perez, P. Ineichen, R. Seals, J. Michalsky and R. Stewart, "Modeling daylight
// availability and irradiance components from direct and global irradiance", Solar Energy
// 44(5), 1990, 271-289, as Radiance's gendaylit and gendaymtx and Ladybug use it:
//
//   relative luminance lv(ζ, γ) = (1 + a exp(b / cos ζ)) (1 + c exp(d γ) + e cos² γ)
//
// ζ the patch centre's zenith angle, γ its angle to the sun, a to e from the 1993 paper's
// table 1 for ε's bin, the sun's zenith angle Z and Δ. The patches' radiances are lv scaled
// so that the horizontal irradiance they give, Σ_p L_p I(p, up) with I the exact cosine
// integral (patch_cosine.h), is the hour's diffuse horizontal irradiance, up to rounding.
//
// Where the model is not defined the sky is isotropic (L = DHI / π on every patch): the sun
// at or below the horizon (twilight diffuse light), and a distribution that gives no light.
// As gendaymtx does, the sun's altitude is taken as at most 87° (keeping the circumsolar
// term off the zenith), ε above 12 as 12, and Δ as at least 0.2 where 1.065 < ε < 2.8.

#include <span>
#include <vector>

#include "shadowgen/sky/sky_patches.h"

namespace shadowgen::sky {

// One hour of weather with the sun's place at its middle.
struct SkyHour {
  double sun_altitude_rad = 0.0;  // above the horizon (apparent)
  double sun_azimuth_rad = 0.0;   // clockwise from true north
  double direct_normal_w_m2 = 0.0;
  double diffuse_horizontal_w_m2 = 0.0;
  int day_of_year = 1;  // 1 to 366, for the Earth's orbit's eccentricity
};

struct PerezParameters {
  double clearness = 1.0;   // ε (Perez 1990, eq. 1)
  double brightness = 0.0;  // Δ (Perez 1990, eq. 2), as taken (the 0.2 floor applied)
  int bin = 0;              // 0 to 7: ε in [1, 1.065), [1.065, 1.23), ..., [6.2, ∞)
  double a = 0.0, b = 0.0, c = 0.0, d = 0.0, e = 0.0;
};

// ε, Δ and a to e of `hour`; meaningful where the sun is up and the diffuse irradiance
// positive.
PerezParameters perez_parameters(const SkyHour& hour);

// The Perez sky over a set of patches, their horizontal cosine integrals computed once.
class PerezSky {
 public:
  explicit PerezSky(std::span<const SkyPatch> patches);

  // The radiance of each patch (W/m²/sr, as its centre sees it), as above; all 0 where the
  // diffuse horizontal irradiance is not positive. O(patches).
  std::vector<double> radiance(const SkyHour& hour) const;

  // I(p, up) of each patch (patch_cosine.h): Σ_p radiance × this is the horizontal
  // irradiance.
  const std::vector<double>& horizontal() const { return horizontal_; }

 private:
  std::span<const SkyPatch> patches_;
  std::vector<double> horizontal_;
  double horizontal_sum_ = 0.0;
};

}  // namespace shadowgen::sky
