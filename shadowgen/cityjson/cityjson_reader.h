#pragma once

// CityJSON files as a scene's model files (docs/cityjson.md): a CityJSON file (versions
// 1.0, 1.1 and 2.0; CityJSON 2.0 specification, https://www.cityjson.org/specs/2.0.1/)
// or a CityJSONSeq file (JSON Lines: a CityJSON header line, then one CityJSONFeature a
// line), read into the faces of its city objects' chosen geometries, in the file's own
// (projected) coordinates, and the site its CRS gives through PROJ.
//
//   SourceModel model = cityjson::read_cityjson("district.city.json", {.lod = "2.2"});
//   // model.faces[i].id "NL.IMBAG.Pand.0363100012185598/4", origin {"cityjson",
//   // "NL.IMBAG.Pand.0363100012185598", "NL.IMBAG.Pand.0363100012185598", "RoofSurface"}
//
// A file is a CityJSONSeq file when its name ends in ".jsonl", or when its first line is
// a JSON object on its own and more lines follow; otherwise it is read whole as one
// CityJSON object. A CityJSONSeq file is read a line at a time, so memory follows its
// longest line and the faces kept.

#include <filesystem>

#include "shadowgen/model/source_model.h"

namespace shadowgen::cityjson {

// Throws InputError naming the file (and, for a CityJSONSeq file, the line), the city
// object's path and the problem.
SourceModel read_cityjson(const std::filesystem::path& file, const SourceOptions& options);

}  // namespace shadowgen::cityjson
