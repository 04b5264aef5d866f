#pragma once

// One EnergyPlus input object of a class this room reads (object_classes.h), as either
// format gives it: an IDF object's fields by position, an epJSON object's by name, both
// turned into fields by key, so that placing surfaces reads one form. A value keeps its
// text: an IDF field as written (trimmed), an epJSON number in its shortest decimal form
// (shadowgen/model/number_text.h), which reads back to the same double and writes the
// decimals the file gave.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "detail/object_classes.h"

namespace shadowgen::energyplus::detail {

struct InputField {
  std::string text;
  std::size_t line = 0;  // the IDF line the field is written on; 0 for epJSON
  std::string label;     // how messages name it: the IDD's field name, or epJSON's path
};

struct InputObject {
  const ClassSpec* spec = nullptr;
  std::string name;      // as written; empty for unnamed objects (Version, ...)
  std::size_t line = 0;  // where the IDF object begins; 0 for epJSON
  std::map<std::string, InputField, std::less<>> fields;  // by FieldSpec::key; blanks left out
  // The vertices' coordinates after `Number of Vertices`, x, y, z of each vertex in turn.
  std::vector<InputField> coordinates;
};

}  // namespace shadowgen::energyplus::detail
