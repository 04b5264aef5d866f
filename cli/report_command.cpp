// `shadowgen report`: area, lit area and lit fraction per (face, light).

#include <cstddef>
#include <cstdint>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/run_progress.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/energyplus_shading.h"
#include "shadowgen/output/irradiation_report.h"
#include "shadowgen/output/report.h"
#include "shadowgen/output/sun_hours_report.h"
#include "shadowgen/weather/epw_reader.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kReportText{
    "report",
    "Area, lit area and lit fraction per (face, light). A scene is generated first; a "
    "shadowed database is read as it is."};

// The most faces --top lists per light (a practical bound: any scene has fewer).
constexpr std::int64_t kMostTopFaces = 1'000'000'000;

struct ReportArgs {
  std::string input;                    // a scene (generated first) or a shadowed database
  std::string format = "csv";           // csv, json or table
  bool csv_safe = false;                // CsvIds::kSpreadsheetSafe
  std::string output;                   // empty: standard output
  std::size_t top = 10;                 // table: most shadowed faces listed per light
  std::vector<double> thresholds{2.0};  // sun-hours: hours the areas are counted at
  std::string weather;                  // irradiation: an EPW file, else the scene's
  ReadingArgs reading;
  MethodArgs method;  // a scene's (LoadOptions::method)
};

// The weather file irradiation reads: --weather, else the scene's `weather`.
Weather weather_for(const ShadowedScene& shadowed, const ReportArgs& args) {
  if (!args.weather.empty()) return weather::read_epw(args.weather);
  if (shadowed.scene.weather) return *shadowed.scene.weather;
  throw InputError(args.input, "",
                   "the irradiation report needs a weather file: a scene's \"weather\" key, or "
                   "--weather FILE.epw");
}

std::string report_text(const ShadowedScene& shadowed, const ReportArgs& args) {
  if (args.format == "json") return report_json(shadowed);
  if (args.format == "energyplus") {
    EnergyPlusShading shading = energyplus_shading(shadowed);
    for (const std::string& warning : shading.warnings) {
      std::cerr << "shadowgen: warning: " << args.input << ": " << warning << '\n';
    }
    return std::move(shading.csv);
  }
  if (args.format == "irradiation") {
    return irradiation_csv(shadowed, weather_for(shadowed, args),
                           args.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact);
  }
  if (args.format == "table") return report_table(shadowed, args.top);
  if (args.format == "sun-hours") {
    if (!shadowed.method.exact()) {
      throw InputError(args.input, "",
                       "holds the lit areas a sampled method estimated, without the exact "
                       "sun-hours regions a sun-hours report needs");
    }
    return sun_hours_csv(shadowed, args.thresholds,
                         args.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact);
  }
  return report_csv(shadowed, args.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact);
}

void run_report(const ReportArgs& args) {
  RunFiles files{{args.input}, {}};
  if (!args.weather.empty()) files.reads.push_back(args.weather);
  if (!args.output.empty()) files.writes.push_back({"-o", args.output});
  LoadOptions options = load_options(args.reading, Accept::kSceneOrDatabase, files);
  // From a scene, a sun path's regions are made only for the report that reads them.
  options.sun_hours_regions = args.format == "sun-hours";
  options.method = args.method.method();
  if (!options.method.exact() && args.format == "sun-hours") {
    throw UsageError(
        "--format sun-hours reports exact sun-hours regions, which a sampled "
        "method does not make (its lit areas give --format energyplus and "
        "irradiation)");
  }
  RunProgress progress(args.input, progress_stream(args.reading.quiet));
  progress.watch(options);
  const ShadowedScene shadowed = load_shadowed(args.input, options);
  progress.finish();  // before the report's warnings, and the report on the terminal
  const std::string report = report_text(shadowed, args);
  if (args.output.empty()) {
    std::cout << report << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write the report to standard output");
  } else {
    write_file_atomically(args.output, report);
  }
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
                   "as EnergyPlus's Schedule:File:Shading reads it)")
      ->check(CLI::IsMember({"csv", "json", "table", "sun-hours", "irradiation", "energyplus"}));
  CLI::Option* weather =
      command->add_option("--weather", args->weather,
                          "with --format irradiation: EnergyPlus weather file (EPW) whose hourly "
                          "direct normal irradiance is used (default: the scene's \"weather\")");
  CLI::Option* threshold =
      command
          ->add_option("--threshold", args->thresholds,
                       "with --format sun-hours: hours of sun (comma-separated or repeated) "
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
  command->callback([args, top, csv_safe, threshold, weather] {
    if (weather->count() > 0 && args->format != "irradiation") {
      throw CLI::ValidationError("--weather", "applies only to --format irradiation");
    }
    if (threshold->count() > 0 && args->format != "sun-hours") {
      throw CLI::ValidationError("--threshold", "applies only to --format sun-hours");
    }
    if (top->count() > 0 && args->format != "table") {
      throw CLI::ValidationError("--top", "applies only to --format table");
    }
    if (csv_safe->count() > 0 && args->format != "csv" && args->format != "sun-hours" &&
        args->format != "irradiation") {
      throw CLI::ValidationError("--csv-safe",
                                 "applies only to --format csv, sun-hours and irradiation");
    }
  });
  return {command, [args] { run_report(*args); }};
}

}  // namespace shadowgen::cli
