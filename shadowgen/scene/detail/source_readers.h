#pragma once

// The reader of each source format's room (shadowgen/energyplus, shadowgen/cityjson,
// shadowgen/gltf), as the scene reader calls it for a meshes[] entry.

#include <filesystem>

#include "detail/source_format.h"
#include "shadowgen/model/source_model.h"

namespace shadowgen::scene::detail {

// Reads `file` as `format` (not SourceFormat::kMesh). Throws InputError naming the file
// (and the object or surface at fault) when it cannot be read.
SourceModel read_source(SourceFormat format, const std::filesystem::path& file,
                        const SourceOptions& options);

}  // namespace shadowgen::scene::detail
