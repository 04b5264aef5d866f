#pragma once

// --sun-hours and --bands, which `render` and `export` share: draw or write one sun path's
// sun-hours regions by band of hours (shadowgen/output/hour_bands.h) instead of the faces
// split by light sets.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/hour_bands.h"
#include "shadowgen/pipeline/load_shadowed.h"

namespace shadowgen::cli {

struct SunHoursArgs {
  std::string path;           // --sun-hours: a sun path's id; empty: no sun-hours map
  std::vector<double> edges;  // --bands: band edges in hours; empty: the default
};

// --sun-hours and --bands (which needs it) on `command`, where `what` says what the
// subcommand makes of the path ("draw", "write"); returns --sun-hours.
CLI::Option* add_sun_hours_options(CLI::App& command, SunHoursArgs& args, const std::string& what);

// What a subcommand that draws or writes the shadowed scene asks of its load: lit polygons
// to draw (LoadOptions::draws); with --sun-hours, the path's sums and not its instants'
// polygons, and a scene without that path refused before its shadows are computed
// (naming `input`).
void load_to_draw(LoadOptions& load, const SunHoursArgs& args, const std::string& input);

// The sun path that `args` names and its bands.
struct SunHoursMap {
  const SunPathHours* path = nullptr;
  HourBands bands;
};

// Throws InputError naming `file` where `shadowed` has no sun path of that id (listing
// those it has), and UsageError for --bands that do not fit the path.
SunHoursMap sun_hours_map(const ShadowedScene& shadowed, const SunHoursArgs& args,
                          const std::string& file);

}  // namespace shadowgen::cli
