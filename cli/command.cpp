#include "cli/command.h"

#include <iostream>
#include <string>

#include "cli/number_options.h"

namespace shadowgen::cli {

void MethodArgs::apply(api::GenerateSettings& settings) const {
  const Method chosen = method();
  settings.method = chosen.kind == MethodKind::kRays        ? api::Method::kRays
                    : chosen.kind == MethodKind::kShadowMap ? api::Method::kShadowMap
                                                            : api::Method::kExact;
  settings.samples = samples;
  settings.resolution = resolution;
}

Method MethodArgs::method() const {
  const MethodKind kind = method_kind(name).value_or(MethodKind::kExact);
  if (kind == MethodKind::kExact && samples_option && samples_option->count() > 0) {
    throw UsageError("--samples applies only to a sampled method (--method rays or shadow-map)");
  }
  if (kind != MethodKind::kShadowMap && resolution_option && resolution_option->count() > 0) {
    throw UsageError("--resolution applies only to --method shadow-map");
  }
  Method method{kind};
  if (kind != MethodKind::kExact) method.samples = samples;
  if (kind == MethodKind::kShadowMap) method.resolution = resolution;
  return method;
}

void add_method_options(CLI::App& command, MethodArgs& args) {
  command
      .add_option("--method", args.name,
                  "how lit areas are found: exact (default; the lit regions themselves), rays "
                  "(stratified points per face, a shadow ray from each, cast with Embree) or "
                  "shadow-map (the same points looked up in depth maps from each light). A "
                  "sampled method estimates lit areas and makes no lit polygon; its database and "
                  "JSON report name it")
      ->check(CLI::IsMember({"exact", "rays", "shadow-map"}));
  args.samples_option =
      command
          .add_option("--samples", args.samples,
                      "with a sampled method: points per face, stratified over its area "
                      "(default " +
                          std::to_string(kDefaultSamples) + ")")
          ->check(whole_number_in(1, kMaxSamples));
  args.resolution_option =
      command
          .add_option("--resolution", args.resolution,
                      "with --method shadow-map: texels along each side of a depth map (default " +
                          std::to_string(kDefaultResolution) + ")")
          ->check(whole_number_in(1, kMaxResolution));
}

void add_lights_option(CLI::App& command, std::vector<std::string>& ids,
                       const std::string& others) {
  command
      .add_option("--lights", ids,
                  "only these lights, by id (comma-separated or repeated), as if the input "
                  "held no other: " +
                      others)
      ->delimiter(',');
}

void add_reading_options(CLI::App& command, ReadingArgs& args, bool progress, bool generates) {
  command.add_flag("--strict", args.strict,
                   "reading warnings are errors: a non-planar polygon (instead of being "
                   "triangulated), an unknown key");
  command.add_option("--threads", args.threads,
                     "worker threads when generating, for the lights and the regions of each "
                     "light's view (0: one per hardware thread); the result does not depend "
                     "on them");
  add_lights_option(command, args.lights,
                    generates ? "a scene's other lights are not generated"
                              : "the other lights' instants are not listed");
  // Declared once above for every subcommand; one that computes no shadow has no use for it.
  if (!generates) command.remove_option(command.get_option("--threads"));
  command.add_flag("--verbose", args.verbose,
                   "every reading warning on its own line (a kind of warning that many faces "
                   "of one mesh, or many of a scene's polygons, draw is otherwise one line)");
  command.add_flag("-q,--quiet", args.quiet,
                   progress ? "do not print reading warnings or the progress line"
                            : "do not print reading warnings");
}

void add_input_option(CLI::App& command, std::string& path) {
  command
      .add_option("input", path,
                  "scene (shadowgen-scene/1) or shadowed database (shadowgen-shadowed/2 or /1)")
      ->required();
}

CLI::Option* add_output_option(CLI::App& command, std::string& path, const std::string& what) {
  return command.add_option("-o,--output", path, what);
}

LoadOptions load_options(const ReadingArgs& args, Accept accept, const RunFiles& files) {
  LoadOptions options;
  options.accept = accept;
  options.strict = args.strict;
  options.generate.threads = args.threads;
  options.verbose = args.verbose;
  options.lights = args.lights;
  guard_outputs(options, files);
  if (!args.quiet) {
    options.on_warning = [](const std::string& warning) {
      std::cerr << "shadowgen: warning: " << warning << '\n';
    };
  }
  return options;
}

api::ReadSettings read_settings(const ReadingArgs& args) {
  api::ReadSettings read;
  read.strict = args.strict;
  read.verbose = args.verbose;
  read.lights = args.lights;
  if (!args.quiet) {
    read.on_warning = [](const std::string& warning) {
      std::cerr << "shadowgen: warning: " << warning << '\n';
    };
  }
  return read;
}

api::LoadSettings load_settings(const ReadingArgs& args, const RunFiles& files) {
  api::LoadSettings settings;
  settings.read = read_settings(args);
  settings.generate.threads = args.threads;
  guard_outputs(settings, files);
  return settings;
}

}  // namespace shadowgen::cli
