#include "cli/sun_hours_options.h"

#include <stdexcept>

#include "cli/command.h"
#include "cli/number_options.h"

namespace shadowgen::cli {

CLI::Option* add_sun_hours_options(CLI::App& command, SunHoursArgs& args, const std::string& what) {
  CLI::Option* path =
      command.add_option("--sun-hours", args.path,
                         "id of a sun path: " + what +
                             " its sun-hours regions, coloured by band of hours, instead of "
                             "the faces split by the lights reaching them");
  command
      .add_option("--bands", args.edges,
                  "with --sun-hours: hours where bands begin, in increasing order "
                  "(comma-separated or repeated; the first band begins at 0; default: whole "
                  "steps of round hours, at most 12 bands)")
      ->delimiter(',')
      ->check(number_in(above(0.0)))
      ->needs(path);
  return path;
}

void load_to_draw(LoadOptions& load, const SunHoursArgs& args, const std::string& input) {
  load.generate.keep_instant_polygons = args.path.empty();
  load.draws = true;
  if (!args.path.empty()) {
    load.on_scene = [path = args.path, input, check = load.on_scene](const Scene& scene) {
      if (check) check(scene);
      require_sun_path(scene, path, input);
    };
  }
}

SunHoursMap sun_hours_map(const ShadowedScene& shadowed, const SunHoursArgs& args,
                          const std::string& file) {
  SunHoursMap map;
  map.path = &sun_path_named(shadowed, args.path, file);
  try {
    map.bands = hour_bands(*map.path, args.edges);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--bands: ") + e.what());
  }
  return map;
}

}  // namespace shadowgen::cli
