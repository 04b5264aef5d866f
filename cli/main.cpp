// shadowgen: exact object-space polygon shadows (Atherton, Weiler and Greenberg 1978).
// Only argument parsing and wiring live here; the work is in the shadowgen library.
//
// Exit codes: 0 success; 1 bad input or output that could not be written (one line
// "shadowgen: <message>" on stderr, no partial output file left behind); 2 a usage error.

#include <CLI/CLI.hpp>
#include <array>
#include <charconv>
#include <cmath>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>

#include "commands.h"

namespace {

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

// "X,Y,Z" as three finite doubles; nullopt when it is not.
std::optional<std::array<double, 3>> parse_triple(std::string_view text) {
  std::array<double, 3> v{};
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (std::size_t i = 0; i < 3; ++i) {
    if (i > 0) {
      if (p == end || *p != ',') return std::nullopt;
      ++p;
    }
    const auto [next, error] = std::from_chars(p, end, v[i]);
    if (error != std::errc() || !std::isfinite(v[i])) return std::nullopt;
    p = next;
  }
  if (p != end) return std::nullopt;
  return v;
}

const CLI::Validator kTriple(
    [](std::string& text) {
      return parse_triple(text) ? std::string() : "expected X,Y,Z (three numbers), got " + text;
    },
    "X,Y,Z");

}  // namespace

int main(int argc, char** argv) {
  using shadowgen::cli::ExportArgs;
  using shadowgen::cli::GenerateArgs;
  using shadowgen::cli::RenderArgs;
  using shadowgen::cli::ReportArgs;

  CLI::App app{"shadowgen: exact polygon shadows (Atherton, Weiler and Greenberg 1978)",
               "shadowgen"};
  app.set_version_flag("--version", std::string("shadowgen ") + SHADOWGEN_VERSION);
  app.require_subcommand(1);
  app.footer("Exit codes: 0 success, 1 bad input or unwritable output, 2 usage error.");

  GenerateArgs generate;
  CLI::App* generate_command = app.add_subcommand(
      "generate",
      "Compute the lit detail polygons of every (face, light) of a scene and write the "
      "shadowed database (shadowgen-shadowed/1). Several scenes are done in turn, each "
      "written before the next is read; a bad one stops the run with exit code 1, leaving "
      "the databases already written. On a terminal a progress line is shown on stderr.");
  generate_command
      ->add_option("scene", generate.scenes, "scene files (shadowgen-scene/1), one or more")
      ->required();
  generate_command
      ->add_option("-o,--output", generate.output,
                   "one scene: the shadowed database to write; several scenes: a folder "
                   "(made when missing) that gets NAME.shadowed.json for each scene NAME.json")
      ->required();
  generate_command->add_flag("--strict", generate.strict,
                             "non-planar polygons are errors instead of being triangulated");
  generate_command->add_option("--threads", generate.threads,
                               "worker threads, one light each (0: one per hardware thread)");
  generate_command->add_flag("-q,--quiet", generate.quiet,
                             "do not print reading warnings or the progress line");

  ReportArgs report;
  CLI::App* report_command =
      app.add_subcommand("report",
                         "Area, lit area and lit fraction per (face, light). A scene is generated "
                         "first; a shadowed database is read as it is.");
  report_command
      ->add_option("input", report.input,
                   "scene (shadowgen-scene/1) or shadowed database (shadowgen-shadowed/1)")
      ->required();
  report_command
      ->add_option("--format", report.format,
                   "csv (default; the spec's rows), json (rows and totals) or table (totals "
                   "per light and the most shadowed faces, for reading)")
      ->check(CLI::IsMember({"csv", "json", "table"}));
  CLI::Option* top_option =
      report_command
          ->add_option("--top", report.top,
                       "with --format table: most shadowed faces listed per light (default 10, "
                       "0 for none)")
          ->check(CLI::NonNegativeNumber);
  report_command->add_option("-o,--output", report.output,
                             "file to write (replaced whole); default: standard output");
  report_command->add_flag("--strict", report.strict, "non-planar polygons of a scene are errors");
  report_command->add_option("--threads", report.threads,
                             "worker threads when generating (0: one per hardware thread)");
  report_command->add_flag("-q,--quiet", report.quiet, "do not print reading warnings");

  ExportArgs export_args;
  CLI::App* export_command = app.add_subcommand(
      "export",
      "Write the shadowed scene as a Wavefront OBJ and its MTL (same stem, \".mtl\", next to "
      "the OBJ): every face split into the regions lit by the same set of lights, grouped by "
      "face id, one material per light set (\"shadow\", \"sun\", \"sun+lamp\"; shadow grey "
      "0.2, lit parts lighter). A scene is generated first; a shadowed database is read as "
      "it is.");
  export_command
      ->add_option("input", export_args.input,
                   "scene (shadowgen-scene/1) or shadowed database (shadowgen-shadowed/1)")
      ->required();
  export_command
      ->add_option("--obj", export_args.obj,
                   "OBJ file to write (replaced whole); the MTL goes next to it")
      ->required();
  export_command->add_flag("--strict", export_args.strict,
                           "non-planar polygons of a scene are errors");
  export_command->add_option("--threads", export_args.threads,
                             "worker threads when generating (0: one per hardware thread)");
  export_command->add_flag("-q,--quiet", export_args.quiet, "do not print reading warnings");

  RenderArgs render;
  std::string eye, target, up;
  CLI::App* render_command = app.add_subcommand(
      "render",
      "Draw the shadowed database from a viewpoint as SVG: hidden surfaces removed from the "
      "eye, each visible face split by the lights reaching it, flat shaded. Reads only the "
      "database; no shadows are recomputed.");
  render_command
      ->add_option("database", render.database, "shadowed database (shadowgen-shadowed/1)")
      ->required();
  CLI::Option_group* camera =
      render_command->add_option_group("camera", "where to look from: exactly one of these");
  camera->add_option("--view", render.view, "id of one of the database's views");
  CLI::Option* eye_option =
      camera->add_option("--eye", eye, "eye position X,Y,Z (with --target)")->check(kTriple);
  camera->require_option(1);
  CLI::Option* target_option =
      render_command->add_option("--target", target, "point looked at X,Y,Z (with --eye)")
          ->check(kTriple);
  CLI::Option* up_option =
      render_command->add_option("--up", up, "up direction X,Y,Z (default 0,0,1)")->check(kTriple);
  CLI::Option* fov_option = render_command->add_option(
      "--fov", render.fov_deg, "full vertical field of view in degrees (default 45)");
  eye_option->needs(target_option);
  target_option->needs(eye_option);
  up_option->needs(eye_option);
  fov_option->needs(eye_option);
  fov_option->check(CLI::Range(0.0, 180.0));
  CLI::Option* ortho_option = render_command->add_flag(
      "--ortho", render.ortho, "orthographic (parallel) projection along target - eye");
  render_command
      ->add_option("--scale", render.scale,
                   "orthographic: pixels per scene unit (default: fit the scene)")
      ->check(CLI::PositiveNumber)
      ->needs(ortho_option);
  render_command->add_option("--svg", render.svg, "SVG file to write")->required();
  render_command->add_option("--width", render.width, "picture width in pixels (default 800)")
      ->check(CLI::Range(1, 1 << 20));
  render_command->add_option("--height", render.height, "picture height in pixels (default 600)")
      ->check(CLI::Range(1, 1 << 20));

  try {
    app.parse(argc, argv);
    if (top_option->count() > 0 && report.format != "table") {
      throw CLI::ValidationError("--top", "applies only to --format table");
    }
    if (app.got_subcommand(render_command)) {
      if (!eye.empty()) render.eye = parse_triple(eye);
      if (!target.empty()) render.target = *parse_triple(target);
      if (!up.empty()) render.up = *parse_triple(up);
    }
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints the help, the version or the error
    return code == 0 ? 0 : kExitUsage;
  }

  try {
    if (app.got_subcommand(generate_command)) {
      shadowgen::cli::run_generate(generate);
    } else if (app.got_subcommand(export_command)) {
      shadowgen::cli::run_export(export_args);
    } else if (app.got_subcommand(render_command)) {
      shadowgen::cli::run_render(render);
    } else {
      shadowgen::cli::run_report(report);
    }
  } catch (const shadowgen::cli::UsageError& e) {
    std::cerr << "shadowgen: " << e.what() << "\nRun with --help for more information.\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    // InputError's message already names the file and the face; I/O errors name the path.
    std::cerr << "shadowgen: " << e.what() << '\n';
    return kExitBadInput;
  }
  return 0;
}
