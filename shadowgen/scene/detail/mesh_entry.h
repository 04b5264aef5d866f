#pragma once

// A scene's meshes[i] entry: its mesh file read as a polygon soup (mesh_reader.h), placed
// by the optional transform, every face record built into a face "<mesh id>/<k>".

#include <filesystem>
#include <string>
#include <vector>

#include "detail/json_entities.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/scene/read_options.h"

namespace shadowgen::detail {

// Appends the mesh's faces to `faces`, in file order, and returns the mesh file read (as
// Face::source_file names it). `scene_path` is the scene file: the mesh's "file" is
// relative to its folder. The mesh id is claimed in `ids`. Throws
// InputError naming the scene (for the entry) or the mesh file (for its faces).
// Warnings are summarised as ReadOptions::verbose says.
std::string read_mesh_entry(const JsonValue& value, const std::filesystem::path& scene_path,
                            const ReadOptions& options, IdRegistry& ids, std::vector<Face>& faces,
                            std::vector<std::string>& warnings);

}  // namespace shadowgen::detail
