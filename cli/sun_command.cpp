// `shadowgen sun`: the instants of a scene's sun lights, where the sun stands at each.

#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/sun_instants.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kSunText{
    "sun",
    "The instants of the scene's sun lights as CSV, one row each: "
    "light,instant,time,step_min,azimuth_deg,elevation_deg,direction_x,direction_y,"
    "direction_z (the sun entry's id, the instant's light id, local standard time, the "
    "minutes it stands for, azimuth clockwise from true north, apparent elevation, and the "
    "unit direction the light travels in scene axes). Computes no shadow."};

struct SunArgs {
  std::string input;   // a scene
  std::string output;  // empty: standard output
  bool csv_safe = false;
  ReadingArgs reading;
};

void run_sun(const SunArgs& args) {
  RunFiles files{{args.input}, {}};
  if (!args.output.empty()) files.writes.push_back({"-o", args.output});
  const Scene scene = load_scene(args.input, load_options(args.reading, Accept::kScene, files));
  const std::string csv =
      sun_instants_csv(scene, args.csv_safe ? CsvIds::kSpreadsheetSafe : CsvIds::kExact);
  if (args.output.empty()) {
    std::cout << csv << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write the instants to standard output");
  } else {
    write_file_atomically(args.output, csv);
  }
}

void add_sun_options(CLI::App& command, SunArgs& args) {
  command.add_option("input", args.input, "scene (shadowgen-scene/1) with a site and sun lights")
      ->required();
  command.add_flag("--csv-safe", args.csv_safe,
                   "put ' before an id that begins with =, +, -, @, a tab or a carriage "
                   "return, which spreadsheets would run as a formula");
  add_output_option(command, args.output,
                    "file to write (replaced whole); default: standard output");
  add_reading_options(command, args.reading, false, false);
}

}  // namespace

Command add_sun_command(CLI::App& app) {
  return make_command<SunArgs>(app, kSunText, add_sun_options, run_sun);
}

}  // namespace shadowgen::cli
