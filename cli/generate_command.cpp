// `shadowgen generate`: scenes in, shadowed databases out.

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/progress.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::cli {
namespace {

constexpr CommandText kGenerateText{
    "generate",
    "Compute the lit detail polygons of every (face, light) of a scene and write the "
    "shadowed database (shadowgen-shadowed/2). Several scenes are done in turn, each "
    "written before the next is read; a bad one stops the run with exit code 1, leaving "
    "the databases already written. On a terminal a progress line is shown on stderr."};

namespace fs = std::filesystem;

// Several scenes are processed in turn, each read, generated and written (atomically)
// before the next is read. Where the databases go (database_paths): with one scene,
// `output` is the database file; with several, `output` is a folder (made when missing)
// and scene DIR/NAME.json gives OUTPUT/NAME.shadowed.json. A bad scene stops the run with
// its error: the databases of the scenes before it stay written, none is written for it
// or for the scenes after it.
struct GenerateArgs {
  std::vector<std::string> scenes;
  std::string output;
  ReadingArgs reading;
  // --keep-instants and --areas-only, named as api::GenerateSettings names them.
  bool keep_instant_polygons = false;
  bool sun_hours_regions = true;
  std::string instants;  // --instants K/N: api::GenerateSettings::shard
  MethodArgs method;     // api::GenerateSettings::method, samples, resolution
};

// Upper bound of N in --instants K/N, the database reader's (far more than any scheduler
// runs at once).
constexpr std::int64_t kMaxShards = 1'000'000;

// "K/N", 1 <= K <= N: shard K - 1 of N. Throws UsageError otherwise.
ShardPlace parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const std::string_view whole(text);
  const std::optional<std::int64_t> n =
      slash == std::string::npos ? std::nullopt
                                 : whole_number_within(whole.substr(slash + 1), 1, kMaxShards);
  const std::optional<std::int64_t> k =
      n ? whole_number_within(whole.substr(0, slash), 1, *n) : std::nullopt;
  if (!k) {
    throw UsageError("--instants " + text +
                     ": expected K/N, shard K of N, 1 <= K <= N <= " + std::to_string(kMaxShards));
  }
  return {static_cast<std::size_t>(*k - 1), static_cast<std::size_t>(*n)};
}

// Two spellings of one file compare equal (weakly_canonical resolves "." and ".." and
// the links of the part that exists).
fs::path comparable(const fs::path& path) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(path, error);
  return error ? fs::absolute(path).lexically_normal() : resolved;
}

// The database path of each scene, in order, by the rule above. Checked before any work:
// throws UsageError when, with several scenes, two of them would be written to the same
// file, a database would replace one of the scenes, or `output` exists and is not a
// folder.
std::vector<fs::path> database_paths(const std::vector<std::string>& scenes,
                                     const std::string& output) {
  if (scenes.size() == 1) {
    refuse_unsafe_outputs({{"-o", output}}, scenes);
    return {fs::path(output)};
  }

  std::error_code error;
  if (fs::exists(output, error) && !fs::is_directory(output, error)) {
    throw UsageError("-o " + output + ": with several scenes, -o names a folder");
  }
  std::set<fs::path> inputs;
  for (const std::string& scene : scenes) inputs.insert(comparable(scene));

  std::vector<fs::path> paths;
  std::set<fs::path> taken;
  for (const std::string& scene : scenes) {
    const fs::path name = fs::path(scene).stem();
    if (name.empty() || name == "." || name == "..") {
      throw UsageError(scene + ": not a scene file name");
    }
    fs::path path = fs::path(output) / name;
    path += ".shadowed.json";
    const fs::path key = comparable(path);
    refuse_unsafe_outputs({{"-o", path.string()}}, scenes);
    if (inputs.count(key) > 0) {
      throw UsageError(scene + ": its database " + path.string() +
                       " would replace one of the scenes");
    }
    if (!taken.insert(key).second) {
      throw UsageError(scene + ": another scene's database is also " + path.string() +
                       " (scenes need different file names)");
    }
    paths.push_back(std::move(path));
  }
  return paths;
}

// Scene `index` of `args`, read and generated, with a progress line when `show_progress`.
api::Shadows generated(const GenerateArgs& args, const fs::path& database, std::size_t index,
                       bool show_progress) {
  const std::vector<OutputFile> writes{{"-o", database.string()}};
  refuse_unsafe_outputs(writes, args.scenes);
  const api::Scene scene = api::read_scene(args.scenes[index], read_settings(args.reading));
  refuse_unsafe_outputs(writes, scene.files());
  api::GenerateSettings settings;
  settings.threads = args.reading.threads;
  settings.keep_instant_polygons = args.keep_instant_polygons;
  settings.sun_hours_regions = args.sun_hours_regions;
  args.method.apply(settings);
  if (!args.instants.empty()) {
    const ShardPlace shard = parse_shard(args.instants);
    settings.shard = api::Shard{shard.index, shard.count};
    if (scene.sun_path_ids().empty()) {
      throw InputError(args.scenes[index], "",
                       "--instants shares out the instants of sun paths, and the scene has "
                       "no sun path (a `sun` light with from, to and step_min)");
    }
  }
  // Ends its line when it goes, so that an error printed afterwards has a line of its own.
  std::optional<ProgressDisplay> progress;
  if (show_progress) {
    ProgressLine line;
    line.scene = args.scenes[index];
    line.scene_index = index;
    line.scene_count = args.scenes.size();
    line.lights_total = scene.light_ids().size();
    progress.emplace(&std::cerr, line);
    settings.on_light_done = [&](const api::LightDone& done) {
      progress->light_done(light_stats(done));
    };
  }
  api::Shadows shadows = api::generate(scene, settings);
  if (progress) progress->finish();
  return shadows;
}

void run_generate(const GenerateArgs& args) {
  if (!args.instants.empty()) {
    parse_shard(args.instants);  // a usage error before any scene is read
    if (args.keep_instant_polygons) {
      throw UsageError("--instants and --keep-instants: a shard keeps its instants' sums only");
    }
  }
  const Method method = args.method.method();  // a usage error before any scene is read
  if (!method.exact() && !args.instants.empty()) {
    throw UsageError(
        "--instants shares out exact sums; a sampled method's lit areas need no "
        "shards");
  }
  if (!method.exact() && args.keep_instant_polygons) {
    throw UsageError("--keep-instants keeps lit polygons, which a sampled method does not make");
  }
  const std::vector<fs::path> paths = database_paths(args.scenes, args.output);
  const bool show_progress = !args.reading.quiet && stderr_is_terminal();
  for (std::size_t i = 0; i < args.scenes.size(); ++i) {
    const api::Shadows shadows = generated(args, paths[i], i, show_progress);
    if (args.scenes.size() > 1) {
      std::error_code error;
      fs::create_directories(args.output, error);
      if (error) {
        throw std::runtime_error("cannot make the folder " + args.output + ": " + error.message());
      }
    }
    api::write_database(shadows, paths[i]);
  }
}

void add_generate_options(CLI::App& command, GenerateArgs& args) {
  command.add_option("scene", args.scenes, "scene files (shadowgen-scene/1), one or more")
      ->required();
  add_output_option(command, args.output,
                    "one scene: the shadowed database to write; several scenes: a folder "
                    "(made when missing) that gets NAME.shadowed.json for each scene NAME.json")
      ->required();
  add_reading_options(command, args.reading, /*progress=*/true);
  add_method_options(command, args.method);
  command.add_flag("--keep-instants", args.keep_instant_polygons,
                   "keep the lit polygons of every instant of a sun path, not only their sun "
                   "hours and lit areas (export and render draw only lights with polygons)");
  command
      .add_option("--instants", args.instants,
                  "K/N: compute shard K of N of every sun path (its share of the instants; "
                  "the other lights in shard 1 alone) and write it for shadowgen merge, "
                  "which joins all N into exactly the database of one run")
      ->type_name("K/N");
  command.add_flag_callback(
      "--areas-only", [&args] { args.sun_hours_regions = false; },
      "sum sun paths into each instant's lit area per face alone, without sun-hours "
      "regions: what the EnergyPlus schedule and irradiation reports need, in time "
      "linear in the instants (the regions of a long path can grow with the square "
      "of its instants); sun-hours reports, maps and band exports refuse it");
}

}  // namespace

Command add_generate_command(CLI::App& app) {
  return make_command<GenerateArgs>(app, kGenerateText, add_generate_options, run_generate);
}

}  // namespace shadowgen::cli
