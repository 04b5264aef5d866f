#pragma once

// --weather, --albedo and --sky, which `report --format radiation` and `render --radiation`
// share: the weather file, the ground's albedo and the sky's patches of the radiation
// report (shadowgen/output/radiation_report.h), named, described and checked in one place.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "shadowgen/shadowgen.h"

namespace shadowgen::cli {

struct RadiationArgs {
  std::string weather;           // an EPW file; empty: the scene's
  std::optional<double> albedo;  // every hour's, else the weather file's
  int sky_subdivisions = api::SkyReportSettings{}.subdivisions;  // MF:N (--sky)
  bool sky_given = false;                                        // --sky was given
};

struct RadiationOptionSet {
  CLI::Option* weather = nullptr;
  CLI::Option* albedo = nullptr;
  CLI::Option* sky = nullptr;
};

// When each option applies, as its help text opens ("with --format radiation").
struct RadiationOptionUse {
  std::string weather, albedo, sky;
};

// The three options on `command`.
RadiationOptionSet add_radiation_options(CLI::App& command, RadiationArgs& args,
                                         const RadiationOptionUse& use);

// The library's settings of `args`.
api::RadiationReportSettings radiation_settings(const RadiationArgs& args);

}  // namespace shadowgen::cli
