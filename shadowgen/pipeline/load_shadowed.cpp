#include "shadowgen/pipeline/load_shadowed.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "shadowgen/database/database_format.h"
#include "shadowgen/json/document.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/pipeline/light_choice.h"
#include "shadowgen/pipeline/method_run.h"
#include "shadowgen/scene/database_reader.h"
#include "shadowgen/scene/scene_reader.h"

namespace shadowgen {
namespace {

void pass_on(const std::vector<std::string>& warnings, const LoadOptions& options) {
  if (!options.on_warning) return;
  for (const std::string& warning : warnings) options.on_warning(warning);
}

// The scene read, as the options ask for it.
Scene prepared(ReadResult read, const std::filesystem::path& path, const LoadOptions& options) {
  pass_on(read.warnings, options);
  keep_lights(read.scene, options.lights, path.string());
  if (options.on_scene) options.on_scene(read.scene);
  return std::move(read.scene);
}

ReadOptions read_options(const LoadOptions& options) {
  ReadOptions read;
  read.strict = options.strict;
  read.verbose = options.verbose;
  return read;
}

ShadowedScene generated(ReadResult read, const std::filesystem::path& path,
                        const LoadOptions& options) {
  Scene scene = prepared(std::move(read), path, options);
  try {
    return shadows_by_method(std::move(scene), method_run(options.method, options.generate))
        .shadowed;
  } catch (const GenerationError& e) {
    // Only here is the file known.
    throw GenerationError(path.string(), e.face_id(), e.light_id(), e.problem());
  }
}

// "method rays, 256 samples per face", as messages name a database's method.
std::string method_text(const ShadowedScene& shadowed) {
  if (shadowed.is_exact()) return "method " + std::string(method_name(MethodKind::kExact));
  const Method& method = shadowed.estimate()->method;
  std::string text = "method " + std::string(method_name(method.kind));
  text += ", " + std::to_string(method.samples) + " samples per face";
  if (method.kind == MethodKind::kShadowMap) {
    text += ", maps of " + std::to_string(method.resolution) + " texels a side";
  }
  return text;
}

// `text`: the database's text where it was read whole (standard input); otherwise the
// file is read as it is parsed (scene/database_reader.h).
ShadowedScene read_shadowed(const std::filesystem::path& path, const std::string* text,
                            const ReadOptions& read, const LoadOptions& options) {
  std::vector<std::string> warnings;
  ShadowedScene shadowed = text != nullptr ? parse_database(*text, path, read, warnings)
                                           : read_database(path, read, warnings);
  pass_on(warnings, options);
  if (shadowed.shard && options.accept != Accept::kShard) {
    throw InputError(path.string(), "",
                     "is shard " + std::to_string(shadowed.shard->index + 1) + " of " +
                         std::to_string(shadowed.shard->count) +
                         " of a sun-path run (generate --instants K/N), not a whole shadowed "
                         "database: join every shard with shadowgen merge first");
  }
  if (options.accept == Accept::kShard) return shadowed;  // merge takes it as it is
  if (!options.method.exact()) {
    throw InputError(path.string(), "",
                     "is a shadowed database, read as it was made (" + method_text(shadowed) +
                         "): a method applies to a scene only");
  }
  if (options.draws && shadowed.estimate()) {
    throw InputError(path.string(), "",
                     "holds the lit areas a sampled method estimated (" + method_text(shadowed) +
                         "), no lit polygons to draw: generate it with --method exact");
  }
  keep_lights(shadowed, options.lights, path.string());
  if (options.generate.keep_instant_polygons && options.on_warning) {
    for (const std::string& sun_path : drop_summed_instants(shadowed, path.string())) {
      options.on_warning(path.string() + ": sun path '" + one_line(sun_path) +
                         "': its instants' lit polygons were summed into sun hours, not kept, "
                         "so its instants are left out (generate --keep-instants keeps them)");
    }
  } else if (options.generate.keep_instant_polygons) {
    drop_summed_instants(shadowed, path.string());
  }
  return shadowed;
}

// Whether `path` can be read twice: first for its format alone, then as what it is. A
// stream (standard input, a pipe such as a shell's <(...)) gives its bytes once: it is
// read whole, once.
bool readable_twice(const std::filesystem::path& path) {
  std::error_code error;
  return path != "-" && !std::filesystem::is_fifo(path, error);
}

[[noreturn]] void refuse(const Document& document, const LoadOptions& options) {
  if (options.accept == Accept::kShard) {
    throw InputError(
        document.path.string(), "",
        "\"format\" is \"" + document.format + "\", expected a shard of a sun-path run (\"" +
            std::string(database::kWrittenFormat) + "\" written by generate --instants K/N)");
  }
  if (options.accept == Accept::kDatabase && document.format == kSceneFormat) {
    throw InputError(document.path.string(), "",
                     "is a scene, not a shadowed database (shadowgen generate makes one)");
  }
  std::string expected = "\"" + std::string(database::kWrittenFormat) + "\"";
  if (options.accept == Accept::kSceneOrDatabase) {
    expected = "\"" + std::string(kSceneFormat) + "\" or " + expected;
  }
  throw InputError(document.path.string(), "",
                   "\"format\" is \"" + document.format + "\", expected " + expected);
}

// Runs `work` on `threads` threads (0: every hardware thread): the reading as much as
// the generation (a scene's polygons are read in parallel).
template <class Work>
auto on_threads(unsigned threads, Work&& work) {
  tbb::task_arena arena(threads != 0 ? static_cast<int>(threads)
                                     : tbb::info::default_concurrency());
  return arena.execute(std::forward<Work>(work));
}

ShadowedScene load(const std::filesystem::path& path, const LoadOptions& options) {
  const ReadOptions read = read_options(options);
  // A scene only: the scene reader's own messages, a wrong "format" included.
  if (options.accept == Accept::kScene) return generated(read_scene(path, read), path, options);

  // A database file is read as it is parsed, never held whole: only its format first.
  if (readable_twice(path)) {
    const std::string format = file_format(path);
    if (database::layout_of(format)) return read_shadowed(path, nullptr, read, options);
  }
  const Document document = read_document(path);
  if (database::layout_of(document.format)) {
    return read_shadowed(path, &document.text, read, options);
  }
  if (document.format != kSceneFormat || options.accept == Accept::kDatabase ||
      options.accept == Accept::kShard) {
    refuse(document, options);
  }
  return generated(parse_scene(document.text, document.path, read), path, options);
}

Scene scene_of(const std::filesystem::path& path, const LoadOptions& options) {
  if (options.accept == Accept::kSceneOrDatabase && readable_twice(path) &&
      database::layout_of(file_format(path))) {
    std::vector<std::string> warnings;
    ShadowedScene shadowed = read_database(path, read_options(options), warnings);
    if (shadowed.shard) {
      throw InputError(path.string(), "",
                       "is a shard of a sun-path run, not a whole shadowed database: join every "
                       "shard with shadowgen merge first");
    }
    return prepared({std::move(shadowed.scene()), std::move(warnings)}, path, options);
  }
  return prepared(read_scene(path, read_options(options)), path, options);
}

}  // namespace

ShadowedScene load_shadowed(const std::filesystem::path& path, const LoadOptions& options) {
  return on_threads(options.generate.threads, [&] { return load(path, options); });
}

Scene load_scene(const std::filesystem::path& path, const LoadOptions& options) {
  return on_threads(options.generate.threads, [&] { return scene_of(path, options); });
}

}  // namespace shadowgen
