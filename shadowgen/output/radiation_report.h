#pragma once

// Radiation report (docs/radiation.md): per face and sun path, the solar energy the face
// receives over the path's instants, direct, diffuse from the sky and reflected from the
// ground, shaded and unshaded. Each instant k stands for the step_min minutes that start
// at it and reads the weather hour holding it (weather/irradiance.h):
//
//   direct(f)  = irradiation_rows's direct energy (irradiation_report.h)
//   diffuse(f) = area(f) Σ_p W(f, p) C_p
//   ground(f)  = area(f) G(f) Σ_k albedo(k) GHI(k) step_min / 60
//
// W the face's lit weights under the sky's patches (sky/sky_exposure.h), C the cumulative
// Perez sky of the path (sky/cumulative_sky.h: instant k's hour, DNI and DHI, with the sun
// where the instant has it, weighted step_min / 60 hours), G the face's ground view factor
// ((1 - cos β)/2 for tilt β) and GHI the hour's global horizontal radiation. The ground
// term is isotropic reflection from an open, unobstructed ground: what the scene hides of
// the ground, and its shadows on the ground, are not counted. Unshaded: W with nothing
// shading (SkyExposure::open_weight), the direct energy's unshaded; the ground term is the
// same. Energies are in Wh when the scene's coordinates are metres.

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/report.h"
#include "shadowgen/sky/sky_exposure.h"

namespace shadowgen {

// The ground's albedo where neither the weather file (999: missing) nor the caller gives
// one: the 0.2 of grass and of EnergyPlus's Site:GroundReflectance default.
inline constexpr double kDefaultAlbedo = 0.2;

struct RadiationOptions {
  // Every hour's albedo, 0 to 1, instead of the weather file's.
  std::optional<double> albedo = std::nullopt;
  // Told once when some hour's albedo is missing and kDefaultAlbedo is taken.
  std::function<void(const std::string& warning)> on_warning = {};
};

// What the sky and the ground give over one sun path.
struct PathSky {
  std::vector<double> radiance_wh;  // [patch]: the cumulative sky, Wh/m²/sr
  double ground_wh_m2 = 0.0;        // Σ_k albedo(k) GHI(k) step_min / 60
};

// One PathSky per sun path of `shadowed`, over `patches`. InputError naming the weather
// file (and its line) for an instant whose hour the file lacks, or whose direct normal,
// diffuse horizontal or global horizontal radiation it marks missing.
std::vector<PathSky> path_skies(const ShadowedScene& shadowed,
                                std::span<const sky::SkyPatch> patches, const Weather& weather,
                                const RadiationOptions& options = {});

struct RadiationRow {
  std::size_t face = 0;
  std::size_t path = 0;  // index into ShadowedScene::sun_paths
  double area = 0.0;
  double direct_wh = 0.0, diffuse_wh = 0.0, ground_wh = 0.0;
  double unshaded_direct_wh = 0.0, unshaded_diffuse_wh = 0.0;
  double total_wh() const { return direct_wh + diffuse_wh + ground_wh; }
  double unshaded_total_wh() const { return unshaded_direct_wh + unshaded_diffuse_wh + ground_wh; }
};

// One row per (face, path), faces in scene order, paths in the order of their first
// instant; `exposure` is shadowed.scene()'s, `skies` path_skies's. Throws what
// irradiation_rows throws.
std::vector<RadiationRow> radiation_rows(const ShadowedScene& shadowed,
                                         const sky::SkyExposure& exposure,
                                         std::span<const PathSky> skies, const Weather& weather);

// The rows of path_skies's skies: what radiation_csv writes and a radiation map
// (view/radiation_map.h) colours, computed once here for both.
std::vector<RadiationRow> radiation_rows(const ShadowedScene& shadowed,
                                         const sky::SkyExposure& exposure, const Weather& weather,
                                         const RadiationOptions& options = {});

// CSV: face_id,sun_path,area,direct_wh,diffuse_wh,ground_wh,total_wh,
// direct_wh_per_area,diffuse_wh_per_area,ground_wh_per_area,total_wh_per_area,
// unshaded_total_wh,unshaded_direct_wh_per_area,unshaded_diffuse_wh_per_area,
// unshaded_total_wh_per_area,total_ratio (total_wh / unshaded_total_wh, 0 where that is
// 0; per area: over the face's area, 0 for a face without area); numbers as the report
// CSV writes them, ids as CsvIds says.
std::string radiation_csv(const ShadowedScene& shadowed, const sky::SkyExposure& exposure,
                          const Weather& weather, const RadiationOptions& options = {},
                          CsvIds ids = CsvIds::kExact);

}  // namespace shadowgen
