#pragma once

// A face's origin in a model file of another tool (FaceOrigin, docs/scene-format.md,
// "Model files"), as the database and the JSON report write it after the face's id:
// "origin": {"format": "cityjson", "object": "...", "group": "...", "semantic": "..."},
// every member written, empty strings included; nothing for a face without origin.

#include "shadowgen/json/json_writer.h"
#include "shadowgen/model/source_model.h"

namespace shadowgen::output::detail {

void write_origin(JsonWriter& out, const FaceOrigin& origin);

}  // namespace shadowgen::output::detail
