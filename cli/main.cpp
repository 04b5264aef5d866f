// shadowgen: exact object-space polygon shadows (Atherton, Weiler and Greenberg 1978).
// Only argument parsing and wiring live here; the work is in the shadowgen library.
//
// Exit codes: 0 success; 1 bad input or output that could not be written (one line
// "shadowgen: <message>" on stderr, no output file left behind); 2 a usage error.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "cli/commands.h"

namespace {

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

}  // namespace

int main(int argc, char** argv) {
  using shadowgen::cli::GenerateArgs;
  using shadowgen::cli::ReportArgs;

  CLI::App app{"shadowgen: exact polygon shadows (Atherton, Weiler and Greenberg 1978)",
               "shadowgen"};
  app.set_version_flag("--version", std::string("shadowgen ") + SHADOWGEN_VERSION);
  app.require_subcommand(1);
  app.footer("Exit codes: 0 success, 1 bad input or unwritable output, 2 usage error.");

  GenerateArgs generate;
  CLI::App* generate_command =
      app.add_subcommand("generate",
                         "Compute the lit detail polygons of every (face, light) of a scene and "
                         "write the shadowed database (shadowgen-shadowed/1).");
  generate_command->add_option("scene", generate.scene, "scene file (shadowgen-scene/1)")
      ->required();
  generate_command->add_option("-o,--output", generate.output, "shadowed database to write")
      ->required();
  generate_command->add_flag("--strict", generate.strict,
                             "non-planar polygons are errors instead of being triangulated");
  generate_command->add_option("--threads", generate.threads,
                               "worker threads, one light each (0: one per hardware thread)");
  generate_command->add_flag("-q,--quiet", generate.quiet, "do not print reading warnings");

  ReportArgs report;
  CLI::App* report_command =
      app.add_subcommand("report",
                         "Area, lit area and lit fraction per (face, light). A scene is generated "
                         "first; a shadowed database is read as it is.");
  report_command
      ->add_option("input", report.input,
                   "scene (shadowgen-scene/1) or shadowed database (shadowgen-shadowed/1)")
      ->required();
  report_command->add_option("--format", report.format, "csv (default) or json")
      ->check(CLI::IsMember({"csv", "json"}));
  report_command->add_option("-o,--output", report.output,
                             "file to write (replaced whole); default: standard output");
  report_command->add_flag("--strict", report.strict, "non-planar polygons of a scene are errors");
  report_command->add_option("--threads", report.threads,
                             "worker threads when generating (0: one per hardware thread)");
  report_command->add_flag("-q,--quiet", report.quiet, "do not print reading warnings");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints the help, the version or the error
    return code == 0 ? 0 : kExitUsage;
  }

  try {
    if (app.got_subcommand(generate_command)) {
      shadowgen::cli::run_generate(generate);
    } else {
      shadowgen::cli::run_report(report);
    }
  } catch (const std::exception& e) {
    // InputError's message already names the file and the face; I/O errors name the path.
    std::cerr << "shadowgen: " << e.what() << '\n';
    return kExitBadInput;
  }
  return 0;
}
