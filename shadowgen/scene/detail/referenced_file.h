#pragma once

// A file a scene names (a mesh, a weather file): relative to the scene's folder, there, and
// a file that can be read.

#include <filesystem>
#include <string>

#include "shadowgen/json/json_reader.h"

namespace shadowgen::scene::detail {

// The path of the file named by `value` (a string), relative to the folder of
// `scene_path`. An InputError at `value` when the name is empty, when no such file is
// there: "<what> 'name' not found (looked for 'path')", and when it is one that cannot be
// read as a file (shadowgen/json/document.h, unreadable_input): "<what> 'name' is a
// folder, not a file (looked for 'path')", "... is not a regular file (a character
// device) ...". A FIFO is read as a stream.
std::filesystem::path referenced_file(const JsonValue& value,
                                      const std::filesystem::path& scene_path,
                                      const std::string& what);

}  // namespace shadowgen::scene::detail
