#pragma once

// IDF text split into objects, as the EnergyPlus Input Output Reference ("Input Data
// File") writes them: fields separated by commas, an object ended by a semicolon, the
// first field its class; `!` begins a comment to the end of the line; an object and a
// field may run over any number of lines; blanks around a field are not part of it.
// Nothing is interpreted here: classes and fields are text.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace shadowgen::energyplus::detail {

struct IdfField {
  std::string text;      // trimmed
  std::size_t line = 0;  // where the field begins (its first character; its comma when blank)
};

struct IdfObject {
  std::vector<IdfField> fields;  // fields[0] is the class; never empty
};

// The objects of `text`. InputError naming `file` and the line for a NUL byte (not IDF
// text) and for an object the file ends inside (no `;`).
std::vector<IdfObject> split_idf(std::string_view text, const std::string& file);

}  // namespace shadowgen::energyplus::detail
