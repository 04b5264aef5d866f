// `shadowgen report`: area, lit area and lit fraction per (face, light), and over groups of
// faces (shadowgen/groups/face_groups.h).

#include <cstddef>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/radiation_options.h"
#include "cli/run_progress.h"
#include "shadowgen/groups/face_groups.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/radiation_report.h"
#include "shadowgen/sky/sky_subdivision.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kReportText{
    "report",
    "Area, lit area and lit fraction per (face, light), and summed over groups of faces "
    "(--group-by, or the scene's groups). A scene is generated first; a shadowed database is "
    "read as it is."};

// The most faces --top lists per light (a practical bound: any scene has fewer).
constexpr std::int64_t kMostTopFaces = 1'000'000'000;

struct ReportArgs {
  std::string input;                    // a scene (generated first) or a shadowed database
  std::string format = "csv";           // csv, json or table
  bool csv_safe = false;                // CsvIds::kSpreadsheetSafe
  std::string output;                   // empty: standard output
  std::size_t top = 10;                 // table: most shadowed faces listed per light
  std::vector<double> thresholds{2.0};  // sun-hours: hours the areas are counted at
  RadiationArgs radiation;              // irradiation (its weather), radiation, sky (its --sky)
  std::vector<std::string> group_by;    // groups/face_groups.h rules; none: the scene's groups
  ReadingArgs reading;
  MethodArgs method;  // a scene's (LoadOptions::method)
};

// The reports whose lights are the sky's patches, not the input's.
bool is_sky(const std::string& format) { return format == "sky" || format == "energyplus-sky"; }

bool is_sun_hours(const std::string& format) {
  return format == "sun-hours" || format == "sun-hours-table";
}

// The formats that sum over groups of faces.
bool groups_apply(const std::string& format) {
  return format == "csv" || format == "json" || format == "table" || format == "sun-hours" ||
         format == "sun-hours-table";
}

api::ReportFormat report_format(const std::string& format) {
  if (format == "json") return api::ReportFormat::kJson;
  if (format == "table") return api::ReportFormat::kTable;
  if (format == "sun-hours") return api::ReportFormat::kSunHours;
  if (format == "sun-hours-table") return api::ReportFormat::kSunHoursTable;
  if (format == "irradiation") return api::ReportFormat::kIrradiation;
  if (format == "energyplus") return api::ReportFormat::kEnergyPlus;
  return api::ReportFormat::kCsv;
}

// The groups the report will sum over, resolved against `scene`, so that a group that
// matches no face is named before any shadow is computed.
void check_groups(const api::Scene& scene, const ReportArgs& args) {
  if (!groups_apply(args.format)) return;
  if (!args.group_by.empty()) {
    (void)api::groups(scene, args.group_by);
  } else if (args.format != "csv" && args.format != "sun-hours") {
    (void)api::groups(scene);
  }
}

// The sky view factors of the input's scene (a database's, as it holds it): its own lights
// are not generated, the sky's patches are.
std::string sky_report_text(const ReportArgs& args, const RunFiles& files) {
  api::LoadSettings settings = load_settings(args.reading, files);
  RunProgress progress(args.input, progress_stream(args.reading.quiet));
  progress.watch(settings);
  api::SkyReportSettings sky{args.radiation.sky_subdivisions, args.csv_safe};
  sky.energyplus = args.format == "energyplus-sky";
  sky.energyplus_fine = args.radiation.sky_given;
  const std::string report = api::sky_report(args.input, settings, sky);
  progress.finish();
  return report;
}

// Direct, diffuse and ground-reflected irradiation: the input's sun paths (a scene's
// generated with lit areas only), then the sky's patches.
std::string radiation_report_text(const ReportArgs& args, const RunFiles& files) {
  api::LoadSettings settings = load_settings(args.reading, files);
  RunProgress progress(args.input, progress_stream(args.reading.quiet));
  progress.watch(settings);
  api::RadiationReportSettings radiation = radiation_settings(args.radiation);
  radiation.csv_safe = args.csv_safe;
  std::vector<std::string> warnings;  // after the progress line
  radiation.on_warning = [&warnings](const std::string& warning) { warnings.push_back(warning); };
  const std::string report = api::radiation_report(args.input, settings, radiation);
  progress.finish();
  for (const std::string& warning : warnings) {
    std::cerr << "shadowgen: warning: " << args.input << ": " << warning << '\n';
  }
  return report;
}

void write_report(const ReportArgs& args, const std::string& report) {
  if (args.output.empty()) {
    std::cout << report << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write the report to standard output");
  } else {
    write_file_atomically(args.output, report);
  }
}

void run_report(const ReportArgs& args) {
  RunFiles files{{args.input}, {}};
  if (!args.radiation.weather.empty()) files.reads.push_back(args.radiation.weather);
  if (!args.output.empty()) files.writes.push_back({"-o", args.output});
  if (is_sky(args.format)) {
    if (args.method.name != "exact") {
      throw UsageError("--format " + args.format +
                       " takes the exact lit areas of every sky patch; --method " +
                       args.method.name + " does not apply");
    }
    write_report(args, sky_report_text(args, files));
    return;
  }
  if (args.format == "radiation") {
    if (args.method.name != "exact") {
      throw UsageError(
          "--format radiation takes the exact lit areas of every sky patch; --method " +
          args.method.name + " does not apply");
    }
    write_report(args, radiation_report_text(args, files));
    return;
  }
  api::LoadSettings settings = load_settings(args.reading, files);
  // From a scene, a sun path's regions are made only for the report that reads them.
  settings.generate.sun_hours_regions = is_sun_hours(args.format);
  args.method.apply(settings.generate);
  if (settings.generate.method != api::Method::kExact && is_sun_hours(args.format)) {
    throw UsageError("--format " + args.format +
                     " reports exact sun-hours regions, which a sampled "
                     "method does not make (its lit areas give --format energyplus and "
                     "irradiation)");
  }
  settings.on_scene = [&args, then = std::move(settings.on_scene)](const api::Scene& scene) {
    if (then) then(scene);
    check_groups(scene, args);
  };
  RunProgress progress(args.input, progress_stream(args.reading.quiet));
  progress.watch(settings);
  const api::Shadows shadows = api::load(args.input, settings);
  progress.finish();  // before the report's warnings, and the report on the terminal
  api::ReportSettings report_settings;
  report_settings.format = report_format(args.format);
  report_settings.group_by = args.group_by;
  report_settings.thresholds = args.thresholds;
  report_settings.top = args.top;
  report_settings.csv_safe = args.csv_safe;
  report_settings.weather = args.radiation.weather;
  report_settings.on_warning = [&args](const std::string& warning) {
    std::cerr << "shadowgen: warning: " << args.input << ": " << warning << '\n';
  };
  // The rows are written on the threads the shadows were made with.
  const std::string report = api::report(shadows, report_settings);
  write_report(args, report);
}

}  // namespace

Command add_report_command(CLI::App& app) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* command = app.add_subcommand(kReportText.name, kReportText.help);
  add_input_option(*command, args->input);
  command
      ->add_option("--format", args->format,
                   "csv (default; the spec's rows), json (rows and totals), table (totals "
                   "per light and the most shadowed faces, for reading) or sun-hours (per "
                   "face and sun path: mean sun hours and the area with at least each "
                   "--threshold) or irradiation (per face and sun path: direct solar energy "
                   "received, from a weather file's direct normal irradiance) or energyplus "
                   "(the sunlit fraction of every face at every time step of one sun path, "
                   "as EnergyPlus's Schedule:File:Shading reads it) or sun-hours-table (per "
                   "sun path and group, or face, the share of its area with at least each "
                   "--threshold, passing at 50 %: the BRE 209 test) or sky (per face: the sky view "
                   "factor with exact obstruction and the view factor of the ground, from the "
                   "sky's patches as lights, --sky) or radiation (per face and sun path: direct, "
                   "diffuse and ground-reflected solar energy, shaded and unshaded, from a "
                   "weather file and the Perez sky over the patches) or energyplus-sky (per "
                   "EnergyPlus surface: EnergyPlus's diffuse sky shading ratios from its 144 sky "
                   "directions and exact lit fractions; with --sky, the ratio over those patches "
                   "beside them)")
      ->check(CLI::IsMember({"csv", "json", "table", "sun-hours", "sun-hours-table", "irradiation",
                             "energyplus", "sky", "radiation", "energyplus-sky"}));
  CLI::Option* group_by =
      command
          ->add_option("--group-by", args->group_by,
                       "sum over groups of faces (comma-separated or repeated), instead of "
                       "the scene's \"groups\": a face pattern (* any run without /, ** any "
                       "run, ? one character, \\ quoting the next) whose matches make one "
                       "group; origin.object, origin.group, origin.semantic or "
                       "origin.format, one group per value of the faces' origins; or "
                       "scene.groups, the scene's own (which json, table and sun-hours-table "
                       "show without --group-by); with --format csv, json, table, sun-hours "
                       "and sun-hours-table")
          ->delimiter(',');
  const RadiationOptionSet radiation_options = add_radiation_options(
      *command, args->radiation,
      {.weather = "with --format irradiation or radiation",
       .albedo = "with --format radiation",
       .sky = "with --format sky or radiation (or energyplus-sky, for a column of its own)"});
  CLI::Option* weather = radiation_options.weather;
  CLI::Option* albedo = radiation_options.albedo;
  CLI::Option* sky_option = radiation_options.sky;
  CLI::Option* threshold =
      command
          ->add_option("--threshold", args->thresholds,
                       "with --format sun-hours or sun-hours-table: hours of sun "
                       "(comma-separated or repeated) "
                       "each giving a column of the area with at least that many (default 2)")
          ->delimiter(',')
          ->check(number_in(at_least(0.0)));
  CLI::Option* top = command
                         ->add_option("--top", args->top,
                                      "with --format table: most shadowed faces listed per "
                                      "light (default 10, 0 for none)")
                         ->check(whole_number_in(0, kMostTopFaces));
  CLI::Option* csv_safe =
      command->add_flag("--csv-safe", args->csv_safe,
                        "CSV: put ' before an id that begins with =, +, -, @, a tab or a "
                        "carriage return, which spreadsheets would run as a formula (ids from "
                        "a scene made elsewhere could carry one)");
  add_output_option(*command, args->output,
                    "file to write (replaced whole); default: standard output");
  add_reading_options(*command, args->reading, /*progress=*/true);
  add_method_options(*command, args->method);
  // Run at the end of parsing, so that the error is reported as a parse error is.
  command->callback([args, top, csv_safe, threshold, weather, albedo, group_by, sky_option] {
    const bool radiation = args->format == "radiation";
    if (sky_option->count() > 0 && !is_sky(args->format) && !radiation) {
      throw CLI::ValidationError("--sky",
                                 "applies only to --format sky, energyplus-sky and radiation");
    }
    if (weather->count() > 0 && args->format != "irradiation" && !radiation) {
      throw CLI::ValidationError("--weather", "applies only to --format irradiation and radiation");
    }
    if (albedo->count() > 0 && !radiation) {
      throw CLI::ValidationError("--albedo", "applies only to --format radiation");
    }
    if (threshold->count() > 0 && !is_sun_hours(args->format)) {
      throw CLI::ValidationError("--threshold",
                                 "applies only to --format sun-hours and sun-hours-table");
    }
    if (group_by->count() > 0 && !groups_apply(args->format)) {
      throw CLI::ValidationError(
          "--group-by", "applies only to --format csv, json, table, sun-hours and sun-hours-table");
    }
    std::unordered_set<std::string> rules;
    for (const std::string& rule : args->group_by) {
      if (const std::optional<std::string> why = groups::group_rule_problem(rule)) {
        throw CLI::ValidationError("--group-by", *why);
      }
      if (!rules.insert(rule).second) {
        throw CLI::ValidationError("--group-by", "'" + rule + "' is given twice");
      }
    }
    if (top->count() > 0 && args->format != "table") {
      throw CLI::ValidationError("--top", "applies only to --format table");
    }
    if (csv_safe->count() > 0 && args->format != "csv" && args->format != "sun-hours" &&
        args->format != "irradiation" && args->format != "sky" && !radiation) {
      throw CLI::ValidationError(
          "--csv-safe", "applies only to --format csv, sun-hours, irradiation, sky and radiation");
    }
  });
  return {command, [args] { run_report(*args); }};
}

}  // namespace shadowgen::cli
