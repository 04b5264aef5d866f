#pragma once

// Reading a `shadowgen-scene/1` file (docs/scene-format.md): JSON polygons with
// holes and mesh files (OBJ, OFF, PLY, STL) with optional transforms. JSON coordinates
// and mesh coordinates keep full double precision (shadowgen/scene/detail/mesh_reader.h).
// Every problem is an InputError naming the file, the face id and what is wrong, with the
// JSON path where the problem is (`lights[1] ('lamp').range.end`); nothing is returned
// half-read. A key the format does not define is a warning naming its path and the key
// probably meant (an error under ReadOptions::strict); a key given twice is an error.

#include <filesystem>
#include <string>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/scene/read_options.h"

namespace shadowgen {

struct ReadResult {
  Scene scene;
  std::vector<std::string> warnings;  // "file: face 'id': what" lines
};

ReadResult read_scene(const std::filesystem::path& path, const ReadOptions& options = {});

// The same from JSON text; mesh files are resolved relative to `path`'s folder, and
// `path` names the file in messages.
ReadResult parse_scene(const std::string& json_text, const std::filesystem::path& path,
                       const ReadOptions& options = {});

}  // namespace shadowgen
