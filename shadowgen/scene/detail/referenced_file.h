#pragma once

// A file a scene names (a mesh, a weather file): relative to the scene's folder, and there.

#include <filesystem>
#include <string>

#include "shadowgen/json/json_reader.h"

namespace shadowgen::detail {

// The path of the file named by `value` (a string), relative to the folder of
// `scene_path`. An InputError at `value` when the name is empty or no such file is there:
// "<what> 'name' not found (looked for 'path')".
std::filesystem::path referenced_file(const JsonValue& value,
                                      const std::filesystem::path& scene_path,
                                      const std::string& what);

}  // namespace shadowgen::detail
