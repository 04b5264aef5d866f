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
  // A scene's generation, as generate_shadows takes it, the same names through: threads
  // also read a scene (its polygons, in parallel; 0: every hardware thread, the result the
  // same for any); with a sampled `method`, only threads and on_light_done apply (and
  // keep_instant_polygons or a shard is a std::invalid_argument, method_run.h). Two also
  // apply to a database: a shard database is refused but where `accept` is kShard
  // (generate.shard makes one, generate --instants K/N), and keep_instant_polygons, set
  // where the caller draws every light's lit polygons (export, render), drops a database's
  // sun paths that kept only lit areas, with a warning.
  GenerateOptions generate;
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
