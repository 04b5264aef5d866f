#include "cli/radiation_options.h"

#include "cli/number_options.h"
#include "cli/sky_option.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/output/radiation_report.h"
#include "shadowgen/sky/sky_subdivision.h"

namespace shadowgen::cli {

RadiationOptionSet add_radiation_options(CLI::App& command, RadiationArgs& args,
                                         const RadiationOptionUse& use) {
  RadiationOptionSet options;
  options.weather = command.add_option("--weather", args.weather,
                                       use.weather +
                                           ": EnergyPlus weather file (EPW) whose hourly "
                                           "irradiance is used (default: the scene's \"weather\")");
  options.albedo =
      command
          .add_option("--albedo", args.albedo,
                      use.albedo +
                          ": the ground's albedo, 0 to 1, at every hour (default: the weather "
                          "file's field 33, else " +
                          shortest(kDefaultAlbedo) + ")")
          ->check(number_in(NumberRange{.low = 0.0, .high = 1.0, .unit = ""}));
  options.sky = add_sky_option(
      command, args.sky_subdivisions, args.sky_given,
      use.sky +
          ": the sky's patches, tregenza (145) or reinhart:N (Reinhart's MF:N, 144 N² + 1 "
          "patches, N from 1 to 64; default " +
          sky::subdivision_name(api::SkyReportSettings{}.subdivisions) + ")");
  return options;
}

api::RadiationReportSettings radiation_settings(const RadiationArgs& args) {
  api::RadiationReportSettings settings;
  settings.subdivisions = args.sky_subdivisions;
  settings.weather = args.weather;
  settings.albedo = args.albedo;
  return settings;
}

}  // namespace shadowgen::cli
