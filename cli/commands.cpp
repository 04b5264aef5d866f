#include "commands.h"

#include <iostream>
#include <set>
#include <stdexcept>
#include <system_error>

#include "cli/progress.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/database.h"
#include "shadowgen/json/document.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/report.h"
#include "shadowgen/scene/scene_reader.h"

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

// Two spellings of one file compare equal (weakly_canonical resolves "." and ".." and
// the links of the part that exists).
std::filesystem::path comparable(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, error);
  return error ? std::filesystem::absolute(path).lexically_normal() : resolved;
}

}  // namespace

std::vector<std::filesystem::path> generate_outputs(const std::vector<std::string>& scenes,
                                                    const std::string& output) {
  if (scenes.size() == 1) return {std::filesystem::path(output)};

  const std::filesystem::path folder = output;
  std::error_code error;
  if (std::filesystem::exists(folder, error) && !std::filesystem::is_directory(folder, error)) {
    throw UsageError("-o " + output + ": with several scenes, -o names a folder");
  }
  std::set<std::filesystem::path> inputs;
  for (const std::string& scene : scenes) inputs.insert(comparable(scene));

  std::vector<std::filesystem::path> outputs;
  std::set<std::filesystem::path> taken;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const std::filesystem::path name = std::filesystem::path(scenes[i]).stem();
    if (name.empty() || name == "." || name == "..") {
      throw UsageError(scenes[i] + ": not a scene file name");
    }
    std::filesystem::path path = folder / name;
    path += ".shadowed.json";
    const std::filesystem::path key = comparable(path);
    if (inputs.count(key) > 0) {
      throw UsageError(scenes[i] + ": its database " + path.string() +
                       " would replace one of the scenes");
    }
    if (!taken.insert(key).second) {
      throw UsageError(scenes[i] + ": another scene's database is also " + path.string() +
                       " (scenes need different file names)");
    }
    outputs.push_back(std::move(path));
  }
  return outputs;
}

void run_generate(const GenerateArgs& args) {
  const std::vector<std::filesystem::path> outputs = generate_outputs(args.scenes, args.output);
  const bool show_progress = !args.quiet && stderr_is_terminal();
  ReadOptions read_options;
  read_options.strict = args.strict;
  for (std::size_t i = 0; i < args.scenes.size(); ++i) {
    const Scene scene = take_scene(read_scene(args.scenes[i], read_options), args.quiet);

    ProgressLine line;
    line.scene = args.scenes[i];
    line.scene_index = i;
    line.scene_count = args.scenes.size();
    line.lights_total = scene.lights.size();
    ProgressDisplay progress(show_progress ? &std::cerr : nullptr, line);
    GenerateOptions options;
    options.threads = args.threads;
    options.on_light_done = progress.callback();
    const ShadowedScene shadowed = generate_shadows(scene, options).shadowed;
    progress.finish();

    if (args.scenes.size() > 1) {
      std::error_code error;
      std::filesystem::create_directories(args.output, error);
      if (error) {
        throw std::runtime_error("cannot make the folder " + args.output + ": " + error.message());
      }
    }
    write_database(shadowed, outputs[i]);
  }
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

  std::string report;
  if (args.format == "json") {
    report = report_json(shadowed);
  } else if (args.format == "table") {
    report = report_table(shadowed, args.top);
  } else {
    report = report_csv(shadowed);
  }
  if (args.output.empty()) {
    std::cout << report << std::flush;
    if (!std::cout) throw std::runtime_error("cannot write the report to standard output");
  } else {
    write_file_atomically(args.output, report);
  }
}

}  // namespace shadowgen::cli
