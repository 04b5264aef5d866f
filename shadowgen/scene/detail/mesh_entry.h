#pragma once

// A scene's meshes[i] entry: its file read by the reader its format calls for
// (source_format.h), placed by the optional transform, every face built into a face of
// the scene:
//   - a mesh file (OBJ, STL, OFF, PLY) as a polygon soup (mesh_reader.h), face record k
//     the face "<mesh id>/<k>";
//   - a model file of another tool (EnergyPlus, CityJSON, glTF) as its room gives it
//     (source_readers.h), source face f the face "<mesh id>/<f.id>", keeping its origin,
//     its vertex rounding (times the transform's stretch) and telling the site.
// The entry's keys: id, file, transform, and lod (CityJSON only: a string or a number, as
// the file writes levels of detail).

#include <filesystem>
#include <string>
#include <vector>

#include "detail/json_entities.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/scene/read_options.h"

namespace shadowgen::scene::detail {

struct MeshEntryRead {
  std::string file;  // the file read, as Face::source_file names it
  SourceSite site;   // what a model file says of the site; empty for a mesh
};

// Appends the mesh's faces to `faces`, in file order, and returns the file read and the
// site its model tells. `scene_path` is the scene file: the mesh's "file" is
// relative to its folder. The mesh id is claimed in `ids`. Throws
// InputError naming the scene (for the entry) or the mesh file (for its faces).
// Warnings are summarised as ReadOptions::verbose says.
MeshEntryRead read_mesh_entry(const JsonValue& value, const std::filesystem::path& scene_path,
                              const ReadOptions& options, IdRegistry& ids, std::vector<Face>& faces,
                              std::vector<std::string>& warnings);

}  // namespace shadowgen::scene::detail
