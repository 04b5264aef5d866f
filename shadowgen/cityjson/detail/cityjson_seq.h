#pragma once

// A CityJSONSeq file (CityJSON 2.0 specification, "Text sequences and streaming with
// CityJSONFeature"; cityjson.org's CityJSONSeq specification): JSON Lines, the first line
// a CityJSON object whose "CityObjects" and "vertices" are empty and whose "transform"
// (required: the features' vertices are integers), "metadata" and "geometry-templates"
// hold for every feature; then one CityJSONFeature a line ({"type": "CityJSONFeature",
// "id", "CityObjects", "vertices", "appearance"}), its vertices its own, placed by the
// first line's transform. Read a line at a time: what is held is the longest line's
// document and the faces kept. Empty lines are skipped. Every message names the line.

#include <cstddef>
#include <istream>
#include <string>

#include "shadowgen/model/source_model.h"

namespace shadowgen::cityjson::detail {

// `first` is the file's first line; `in` reads the lines after it, from line `next_line`
// on. `file` names the file in messages. Throws InputError.
SourceModel read_cityjson_seq(const std::string& first, std::size_t next_line, std::istream& in,
                              const std::string& file, const SourceOptions& options);

// `problem` (an InputError's, or a warning's after "file: ") as said of line `line`: the
// JSON reader's "line 1, column 7: ..." becomes "line <line>, column 7: ...", anything
// else gets "line <line>: " before it.
std::string on_line(const std::string& problem, std::size_t line);

}  // namespace shadowgen::cityjson::detail
