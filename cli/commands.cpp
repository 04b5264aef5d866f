#include "cli/commands.h"

#include <iostream>
#include <stdexcept>

#include "shadowgen/atomic_file.h"
#include "shadowgen/database.h"
#include "shadowgen/document.h"
#include "shadowgen/generate.h"
#include "shadowgen/input_error.h"
#include "shadowgen/report.h"
#include "shadowgen/scene_reader.h"

namespace shadowgen::cli {
namespace {

Scene take_scene(ReadResult result, bool quiet) {
  if (!quiet) {
    for (const std::string& warning : result.warnings) {
      std::cerr << "shadowgen: warning: " << warning << '\n';
    }
  }
  return std::move(result.scene);
}

ShadowedScene generate(const Scene& scene, unsigned threads) {
  GenerateOptions options;
  options.threads = threads;
  return generate_shadows(scene, options).shadowed;
}

}  // namespace

void run_generate(const GenerateArgs& args) {
  ReadOptions read_options;
  read_options.strict = args.strict;
  const Scene scene = take_scene(read_scene(args.scene, read_options), args.quiet);
  write_database(generate(scene, args.threads), args.output);
}

void run_report(const ReportArgs& args) {
  const Document document = read_document(args.input);
  ShadowedScene shadowed;
  if (document.format == kSceneFormat) {
    ReadOptions read_options;
    read_options.strict = args.strict;
    const Scene scene =
        take_scene(parse_scene(document.text, document.path, read_options), args.quiet);
    shadowed = generate(scene, args.threads);
  } else if (document.format == kShadowedFormat) {
    shadowed = parse_database(document.text, document.path);
  } else {
    throw InputError(args.input, "",
                     "\"format\" is \"" + document.format + "\", expected \"" +
                         std::string(kSceneFormat) + "\" or \"" + std::string(kShadowedFormat) +
                         "\"");
  }

  const std::string report = args.format == "json" ? report_json(shadowed) : report_csv(shadowed);
  if (args.output.empty()) {
    std::cout << report << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write the report to standard output");
  } else {
    write_file_atomically(args.output, report);
  }
}

}  // namespace shadowgen::cli
