// `shadowgen report`: area, lit area and lit fraction per (face, light).

#include <cstddef>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli/command.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/report.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kReportText{
    "report",
    "Area, lit area and lit fraction per (face, light). A scene is generated first; a "
    "shadowed database is read as it is."};

struct ReportArgs {
  std::string input;           // a scene (generated first) or a shadowed database
  std::string format = "csv";  // csv, json or table
  bool csv_safe = false;       // CsvIds::kSpreadsheetSafe
  std::string output;          // empty: standard output
  std::size_t top = 10;        // table: most shadowed faces listed per light
  ReadingArgs reading;
};

std::string report_text(const ShadowedScene& shadowed, const ReportArgs& args) {
  if (args.format == "json") return report_json(shadowed);
  if (args.format == "table") return report_table(shadowed, args.top);
  return report_csv(shadowed, args.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact);
}

void run_report(const ReportArgs& args) {
  if (!args.output.empty()) refuse_input_as_output("-o", args.output, args.input);
  std::vector<OutputFile> outputs;
  if (!args.output.empty()) outputs.push_back({"-o", args.output});
  const ShadowedScene shadowed = load_shadowed(
      args.input, load_options(args.reading, Accept::kSceneOrDatabase, std::move(outputs)));
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
                   "csv (default; the spec's rows), json (rows and totals) or table (totals "
                   "per light and the most shadowed faces, for reading)")
      ->check(CLI::IsMember({"csv", "json", "table"}));
  CLI::Option* top = command
                         ->add_option("--top", args->top,
                                      "with --format table: most shadowed faces listed per "
                                      "light (default 10, 0 for none)")
                         ->check(CLI::NonNegativeNumber);
  CLI::Option* csv_safe =
      command->add_flag("--csv-safe", args->csv_safe,
                        "CSV: put ' before an id that begins with =, +, -, @, a tab or a "
                        "carriage return, which spreadsheets would run as a formula (ids from "
                        "a scene made elsewhere could carry one)");
  add_output_option(*command, args->output,
                    "file to write (replaced whole); default: standard output");
  add_reading_options(*command, args->reading);
  // Run at the end of parsing, so that the error is reported as a parse error is.
  command->callback([args, top, csv_safe] {
    if (top->count() > 0 && args->format != "table") {
      throw CLI::ValidationError("--top", "applies only to --format table");
    }
    if (csv_safe->count() > 0 && args->format != "csv") {
      throw CLI::ValidationError("--csv-safe", "applies only to --format csv");
    }
  });
  return {command, [args] { run_report(*args); }};
}

}  // namespace shadowgen::cli
