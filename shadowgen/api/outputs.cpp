#include "shadowgen/api/outputs.h"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <utility>

#include "detail/handles.h"
#include "detail/on_threads.h"
#include "detail/translated.h"
#include "shadowgen/groups/face_groups.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/database.h"
#include "shadowgen/output/energyplus_shading.h"
#include "shadowgen/output/energyplus_sky_report.h"
#include "shadowgen/output/gltf_export.h"
#include "shadowgen/output/irradiation_report.h"
#include "shadowgen/output/obj_export.h"
#include "shadowgen/output/radiation_report.h"
#include "shadowgen/output/report.h"
#include "shadowgen/output/sky_report.h"
#include "shadowgen/output/sun_hours_report.h"
#include "shadowgen/output/sun_hours_table.h"
#include "shadowgen/pipeline/load_shadowed.h"
#include "shadowgen/sky/energyplus_sky.h"
#include "shadowgen/sky/sky_exposure.h"
#include "shadowgen/sky/sky_lights.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/render.h"
#include "shadowgen/view/svg_writer.h"
#include "shadowgen/weather/epw_reader.h"

namespace shadowgen::api {
namespace {

// The groups a report sums over: group_by's; else, in the formats for people and in JSON,
// the scene's own. The CSVs keep the spec's shape unless group_by asks for groups.
std::vector<groups::FaceGroup> report_groups(const shadowgen::Scene& scene,
                                             const ReportSettings& settings) {
  switch (settings.format) {
    case ReportFormat::kCsv:
    case ReportFormat::kSunHours:
      return settings.group_by.empty() ? std::vector<groups::FaceGroup>{}
                                       : groups::groups_by(scene, settings.group_by);
    case ReportFormat::kJson:
    case ReportFormat::kTable:
    case ReportFormat::kSunHoursTable:
      return settings.group_by.empty() ? groups::scene_groups(scene)
                                       : groups::groups_by(scene, settings.group_by);
    case ReportFormat::kIrradiation:
    case ReportFormat::kEnergyPlus:
      return {};
  }
  return {};
}

// The weather file a report reads: `file`, else the scene's.
Weather weather_for(const ShadowedScene& shadowed, const std::string& file,
                    const std::string& report) {
  if (!file.empty()) return weather::read_epw(file);
  if (shadowed.scene().weather) return *shadowed.scene().weather;
  throw shadowgen::InputError(shadowed.scene().file, "",
                              "the " + report +
                                  " report needs a weather file: a scene's \"weather\" key, or "
                                  "--weather FILE.epw");
}

std::string report_text(const ShadowedScene& shadowed, const ReportSettings& settings) {
  const std::vector<groups::FaceGroup> groups = report_groups(shadowed.scene(), settings);
  const CsvIds ids = settings.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact;
  switch (settings.format) {
    case ReportFormat::kJson:
      return report_json(shadowed, groups);
    case ReportFormat::kEnergyPlus: {
      EnergyPlusShading shading = energyplus_shading(shadowed);
      if (settings.on_warning) {
        for (const std::string& warning : shading.warnings) settings.on_warning(warning);
      }
      return std::move(shading.csv);
    }
    case ReportFormat::kIrradiation:
      return irradiation_csv(shadowed, weather_for(shadowed, settings.weather, "irradiation"), ids);
    case ReportFormat::kTable:
      return report_table(shadowed, settings.top, groups);
    case ReportFormat::kSunHours:
    case ReportFormat::kSunHoursTable:
      if (shadowed.estimate()) {
        throw shadowgen::InputError(
            shadowed.scene().file, "",
            "holds the lit areas a sampled method estimated, without the exact "
            "sun-hours regions a sun-hours report needs");
      }
      if (settings.format == ReportFormat::kSunHoursTable) {
        return sun_hours_table(shadowed, settings.thresholds, groups);
      }
      return sun_hours_csv(shadowed, settings.thresholds, ids, groups);
    case ReportFormat::kCsv:
      break;
  }
  return report_csv(shadowed, ids, groups);
}

// The sky's options for `scene` lit by `lights` (their patches' lights, sky_scene), of
// MF:`subdivisions`, generated on settings.generate's threads, shown to settings.on_scene as
// a scene of one light each and counted by settings.generate.on_light_done.
sky::SkyOptions sky_options_for(const shadowgen::Scene& scene, int subdivisions,
                                const std::vector<sky::SkyPatch>& lights,
                                const LoadSettings& settings) {
  sky::SkyOptions sky_options;
  sky_options.subdivisions = subdivisions;
  sky_options.threads = settings.generate.threads;
  if (settings.on_scene) settings.on_scene(detail::scene_view(sky::sky_scene(scene, lights)));
  if (settings.generate.on_light_done) {
    sky_options.on_light_done = [&settings](std::size_t patch, const LightStats& stats) {
      settings.generate.on_light_done(
          {patch, stats.faces_considered, stats.lit_polygons, stats.seconds});
    };
  }
  return sky_options;
}

// `scene`'s exposure to the sky of MF:`subdivisions`, as sky_options_for says.
sky::SkyExposure exposure_of(const shadowgen::Scene& scene, int subdivisions,
                             const LoadSettings& settings) {
  return sky::sky_exposure(
      scene, sky_options_for(scene, subdivisions, sky::reinhart_patches(subdivisions), settings));
}

// What draws lit polygons needs exact shadows.
void require_exact(const ShadowedScene& shadowed, const std::string& what) {
  if (shadowed.is_exact()) return;
  throw shadowgen::InputError(
      shadowed.scene().file, "",
      "holds the lit areas a sampled method estimated, no lit polygons " + what);
}

}  // namespace

static_assert(SkyReportSettings{}.subdivisions == sky::kDefaultSubdivisions,
              "the library's default sky is the sky room's");

std::string sky_report(const std::string& path, const LoadSettings& settings,
                       const SkyReportSettings& sky_settings) {
  return detail::translated([&] {
    LoadOptions options;
    options.strict = settings.read.strict;
    options.verbose = settings.read.verbose;
    options.on_warning = settings.read.on_warning;
    const shadowgen::Scene scene = load_scene(path, options);
    if (sky_settings.energyplus) {
      require_energyplus_surface_names(scene);
      sky::SkyOptions fine;
      fine.subdivisions = sky_settings.subdivisions;
      const std::vector<sky::SkyPatch> lights =
          sky::energyplus_sky_lights(fine, sky_settings.energyplus_fine);
      return energyplus_sky_csv(
          scene, sky::energyplus_sky_shading(
                     scene, sky_options_for(scene, sky_settings.subdivisions, lights, settings),
                     sky_settings.energyplus_fine));
    }
    const sky::SkyExposure exposure = exposure_of(scene, sky_settings.subdivisions, settings);
    return sky_view_factor_csv(scene, exposure,
                               sky_settings.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact);
  });
}

std::string radiation_report(const std::string& path, const LoadSettings& settings,
                             const RadiationReportSettings& radiation) {
  if (radiation.albedo && !(*radiation.albedo >= 0.0 && *radiation.albedo <= 1.0)) {
    throw std::invalid_argument("an albedo lies between 0 and 1");
  }
  LoadSettings sun_paths = settings;
  sun_paths.generate.sun_hours_regions = false;
  const Shadows shadows = load(path, sun_paths);
  return detail::on_threads(shadows, [&] {
    const ShadowedScene& shadowed = detail::model(shadows);
    const Weather weather = weather_for(shadowed, radiation.weather, "radiation");
    const sky::SkyExposure exposure =
        exposure_of(shadowed.scene(), radiation.subdivisions, settings);
    RadiationOptions options;
    options.albedo = radiation.albedo;
    options.on_warning = radiation.on_warning;
    return radiation_csv(shadowed, exposure, weather, options,
                         radiation.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact);
  });
}

std::string report(const Shadows& shadows, const ReportSettings& settings) {
  return detail::on_threads(shadows, [&] { return report_text(detail::model(shadows), settings); });
}

void write_database(const Shadows& shadows, const std::string& path) {
  detail::on_threads(shadows, [&] { shadowgen::write_database(detail::model(shadows), path); });
}

void write_obj(const Shadows& shadows, const std::string& path, ObjLayout layout) {
  detail::on_threads(shadows, [&] {
    const ShadowedScene& shadowed = detail::model(shadows);
    require_exact(shadowed, "for an OBJ");
    const std::filesystem::path obj_path = path;
    const std::filesystem::path mtl_path =
        obj_path.parent_path() / (obj_name(obj_path.stem().string()) + ".mtl");
    if (mtl_path == obj_path || obj_path.filename().empty()) {
      throw shadowgen::InputError(path, "",
                                  "not a usable OBJ file name: the MTL file goes next to it, "
                                  "named with the same stem and \".mtl\"");
    }
    const std::string mtl_name = mtl_path.filename().string();
    const ObjFiles texts = layout == ObjLayout::kByLight ? obj_export_by_light(shadowed, mtl_name)
                                                         : obj_export(shadowed, mtl_name);
    write_files_atomically({{mtl_path, texts.mtl}, {obj_path, texts.obj}});
  });
}

void write_gltf(const Shadows& shadows, const std::string& path) {
  detail::on_threads(shadows, [&] {
    const std::optional<GltfForm> form = gltf_form_of(path);
    if (!form) {
      throw std::invalid_argument(path + ": a glTF file's name ends in \".glb\" or \".gltf\"");
    }
    const ShadowedScene& shadowed = detail::model(shadows);
    require_exact(shadowed, "for a glTF file");
    write_file_atomically(path, gltf_export(shadowed, *form));
  });
}

void write_svg(const Shadows& shadows, const std::string& path, const std::string& view_id,
               int width, int height) {
  detail::on_threads(shadows, [&] {
    const ShadowedScene& shadowed = detail::model(shadows);
    require_exact(shadowed, "to draw");
    const ViewSpec* spec = nullptr;
    for (const ViewSpec& view : shadowed.scene().views) {
      if (view.id == view_id) spec = &view;
    }
    if (spec == nullptr) {
      throw shadowgen::InputError(shadowed.scene().file, "", "no view with id '" + view_id + "'");
    }
    RenderOptions options;
    options.width = width;
    options.height = height;
    const Picture picture = render(shadowed, camera_from_view(*spec, false), options);
    write_file_atomically(path, svg_document(picture));
  });
}

}  // namespace shadowgen::api
