#pragma once

// Every output of shadows: reports as text, and the database, OBJ, glTF and SVG files.
// Files are written whole through a temporary file and a rename: on an error nothing is
// left half-written (std::runtime_error naming the path).
//
//   shadowgen::api::Shadows shadows = shadowgen::api::load("courtyard.json");
//   std::cout << shadowgen::api::report(shadows);  // the report CSV
//   shadowgen::api::write_database(shadows, "courtyard.shadowed.json");
//   shadowgen::api::write_svg(shadows, "courtyard.svg", "main");

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "shadowgen/api/shadows.h"

namespace shadowgen::api {

// The report formats of `shadowgen report --format` (docs/scene-format.md).
enum class ReportFormat {
  kCsv,            // area, lit area, lit fraction per (face, light)
  kJson,           // the rows, with totals per light and for the scene
  kTable,          // totals per light and the most shadowed faces, for people
  kSunHours,       // per face and sun path: mean, least and most hours, area at thresholds
  kSunHoursTable,  // per sun path and group: the share with at least each threshold (BRE 209)
  kIrradiation,    // per face and sun path: direct solar energy from a weather file
  kEnergyPlus,     // a sun path's sunlit fractions as EnergyPlus's Schedule:File:Shading
};

struct ReportSettings {
  ReportFormat format = ReportFormat::kCsv;
  // kCsv, kJson, kTable, kSunHours, kSunHoursTable: sum over these groups (rules as
  // groups() takes them); with none, the scene's own groups in kJson, kTable and
  // kSunHoursTable.
  std::vector<std::string> group_by = {};
  std::vector<double> thresholds{2.0};  // kSunHours, kSunHoursTable: hours
  std::size_t top = 10;                 // kTable: most shadowed faces listed per light
  bool csv_safe = false;                // CSVs: a ' before ids a spreadsheet would run as formulas
  std::string weather = {};             // kIrradiation: an EPW file; empty: the scene's weather
  std::function<void(const std::string& warning)> on_warning = {};  // kEnergyPlus's warnings
};

// The report's text, as `shadowgen report` writes it, byte for byte.
std::string report(const Shadows& shadows, const ReportSettings& settings = {});

struct SkyReportSettings {
  int subdivisions = 8;   // Reinhart MF:N (1: Tregenza's 145 patches), 1 to 64
  bool csv_safe = false;  // a ' before ids a spreadsheet would run as formulas
  // `report --format energyplus-sky` instead: EnergyPlus's diffuse sky shading ratios per
  // surface from its 144 sky directions, and with `energyplus_fine` the ratio over the
  // `subdivisions` patches beside them (their lights after EnergyPlus's 144).
  bool energyplus = false;
  bool energyplus_fine = false;
};

// `shadowgen report --format sky` (docs/sky.md), byte for byte: every face's sky view
// factor with exact obstruction and its ground view factor, as CSV, for the scene at `path`
// or the scene a database holds; neither's own lights are generated, the sky's patches
// are, one light each. Of `settings`: read; generate.threads and generate.on_light_done
// (light k is patch k); on_scene, called with the scene whose lights are the patches.
// With sky.energyplus, `shadowgen report --format energyplus-sky`'s CSV instead.
std::string sky_report(const std::string& path, const LoadSettings& settings = {},
                       const SkyReportSettings& sky = {});

struct RadiationReportSettings {
  int subdivisions = 8;               // the sky's patches, as SkyReportSettings's
  std::string weather = {};           // an EPW file; empty: the scene's weather
  std::optional<double> albedo = {};  // 0 to 1, every hour's; else the weather file's
  bool csv_safe = false;              // a ' before ids a spreadsheet would run as formulas
  std::function<void(const std::string& warning)> on_warning = {};  // a missing albedo
};

// `shadowgen report --format radiation` (docs/radiation.md), byte for byte: per face and
// sun path, direct, diffuse and ground-reflected irradiation, shaded and unshaded, as CSV,
// for the scene at `path` (its sun paths generated with lit areas only) or a database. The
// sky's patches are generated as sky_report's are, after the sun paths. Of `settings`:
// read; generate.threads and generate.on_light_done (the sun paths' lights, then the
// patches); on_scene, called with the scene read, then with the sky's scene. Throws
// InputError for an input without sun paths or weather and for the weather file's missing
// hours and values; std::invalid_argument for an albedo outside [0, 1].
std::string radiation_report(const std::string& path, const LoadSettings& settings = {},
                             const RadiationReportSettings& radiation = {});

// The shadowed database (shadowgen-shadowed/1), which load() reads back.
void write_database(const Shadows& shadows, const std::string& path);

enum class ObjLayout {
  kLightSets,  // each face split by the set of lights reaching it, a material per set
  kByLight,    // each face whole in shadow, then one group per light of its lit polygons
};

// An OBJ file and its MTL beside it (the OBJ's stem, ".mtl"). Exact shadows only.
void write_obj(const Shadows& shadows, const std::string& path,
               ObjLayout layout = ObjLayout::kLightSets);

// A glTF 2.0 file of the faces split by light sets: binary for ".glb", JSON for ".gltf"
// (std::invalid_argument for another extension). Exact shadows only.
void write_gltf(const Shadows& shadows, const std::string& path);

// An SVG picture from the scene's view `view_id`, `width` × `height` pixels, as `shadowgen
// render --view` draws it. Exact shadows only; InputError for a view the scene lacks.
void write_svg(const Shadows& shadows, const std::string& path, const std::string& view_id,
               int width = 800, int height = 600);

}  // namespace shadowgen::api
