#pragma once

// The shadowed database (JSON): the scene as read plus the lit detail polygons of every
// (face, light). Written and read back losslessly: every double
// is printed in the shortest form that reads back to the same value.
//
// The layout, its versions and keys: shadowgen/database/database_format.h. The writer
// writes the indexed layout (shadowgen-shadowed/2) unless told otherwise, one light, view,
// region or part a line.
// Reading, with the checks a database must pass: shadowgen/scene/database_reader.h.

#include <filesystem>
#include <string>

#include "shadowgen/database/database_format.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

// Throws std::invalid_argument (naming the face or light) for what the format cannot
// hold: a non-finite number, a loop of fewer than three vertices, a face without parts,
// or duplicate ids.
std::string database_json(const ShadowedScene& shadowed,
                          database::Layout layout = database::Layout::kIndexed);

// Writes through a temporary file in the same folder and a rename: never a partial file.
// The text is streamed into it, never held whole.
void write_database(const ShadowedScene& shadowed, const std::filesystem::path& path,
                    database::Layout layout = database::Layout::kIndexed);

}  // namespace shadowgen
