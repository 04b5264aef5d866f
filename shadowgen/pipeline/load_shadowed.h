#pragma once

// From an input file to a shadowed scene: the one place that tells a scene from a
// shadowed database, by the document's top-level "format" key (shadowgen/json/document.h).
// A scene is read and its shadows generated; a database is read as it is. The command
// line's subcommands all load their input here.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {

// Which inputs a caller takes.
enum class Accept {
  kSceneOrDatabase,  // a scene is generated, a database read as it is (report, export)
  kScene,            // a scene only, read as read_scene reads it (generate)
  kDatabase,         // a shadowed database only; a scene is refused, saying so (render)
  kShard,            // a shard of a sun-path run only (merge)
};

struct LoadOptions {
  Accept accept = Accept::kSceneOrDatabase;
  bool strict = false;   // ReadOptions::strict, for a scene and a database alike
  bool verbose = false;  // ReadOptions::verbose
  // Threads reading a scene (its polygons, in parallel) and generating its shadows
  // (GenerateOptions::threads); 0: every hardware thread. The result is the same for any.
  unsigned threads = 0;
  // GenerateOptions::sun_hours_regions, for a scene.
  bool sun_hours_regions = true;
  // GenerateOptions::shard: a scene's run cut into shards (generate --instants K/N). A
  // shard database is refused but where `accept` is kShard.
  std::optional<ShardPlace> shard;
  // Whether the caller draws every light's lit polygons (export, render): a scene's sun
  // paths keep their instants' polygons (GenerateOptions::keep_instant_polygons); a
  // database's sun paths that kept only lit areas are dropped, with a warning.
  bool instant_polygons = false;
  // How a scene's lit areas are found (generate, report): a sampled method estimates them
  // (shadowgen/sampled/estimate.h) and makes no lit polygon. A database is read as it is
  // made: with a sampled method asked for, it is refused, as it is where the caller draws
  // (`draws`) and the database holds a sampled method's areas.
  Method method;
  // Whether the caller draws lit polygons or sun-hours regions (export, render), which a
  // sampled method does not make: a scene is generated exactly, a sampled database refused.
  bool draws = false;
  // When not empty, only these of the input's lights (light_choice.h): a scene's others
  // are not generated, a database's are dropped.
  std::vector<std::string> lights;
  // Each reading warning, a line naming the file; dropped when empty.
  std::function<void(const std::string& warning)> on_warning;
  // A scene once read, before its shadows are generated (to start a progress display).
  std::function<void(const Scene& scene)> on_scene;
  // GenerateOptions::on_light_done.
  std::function<void(std::size_t light, const LightStats& stats)> on_light_done;
};

// Throws InputError naming the file for bad input (a format the caller does not take
// included), and GenerationError naming the file, the face and the light where shadows
// cannot be generated. Standard input ("-") and a pipe (a FIFO) are read whole, once; a
// file is scanned for its format, then read as what it is.
ShadowedScene load_shadowed(const std::filesystem::path& path, const LoadOptions& options = {});

// A scene read as load_shadowed reads one (warnings passed on, lights kept, on_scene
// called), without generating its shadows: for what needs the scene alone (the sun's
// instants). `threads` read the scene; `on_light_done` is not used. With `accept` kSceneOrDatabase,
// a shadowed database gives the scene it holds (its faces, lights and views, as read and checked);
// with any other, a database is an error, as for Accept::kScene.
Scene load_scene(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace shadowgen
