#pragma once

// A geometry's level of detail, as the file writes it (CityJSON 2.0 specification,
// "Geometry Objects"): a string of a number ("2", "2.2") since version 1.1, a number
// (2, 2.2) in version 1.0. Levels are ordered by their numbers; a level asked for by name
// (SourceOptions::lod, the scene entry's "lod") is compared as the file writes it: the
// same string, or for a number the same number ("2.2" picks 1.0's 2.2).

#include <string>

#include "shadowgen/json/json_reader.h"

namespace shadowgen::cityjson::detail {

struct Lod {
  std::string text;  // as written; a number in its shortest form ("2.2", "2")
  double value = 0.0;
  bool written_as_number = false;

  // Whether `asked` names this level.
  bool matches(const std::string& asked) const;
};

// Fails unless `value` is a number, or a string of one (such as "2" or "2.2"), at least 0.
Lod read_lod(const JsonValue& value);

}  // namespace shadowgen::cityjson::detail
