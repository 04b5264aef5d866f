#pragma once

// The objects of an IDF file that this room reads (object_classes.h), their fields put
// by key where the file's Version places them; every other object is passed over.

#include <string>
#include <string_view>
#include <vector>

#include "detail/input_object.h"

namespace shadowgen::energyplus::detail {

// InputError naming `file` and the line where the file has no Version object, more than
// one, or one that is not a version from kOldestVersion to kNewestVersion
// (file_version.h), and where split_idf finds the text malformed.
std::vector<InputObject> idf_objects(std::string_view text, const std::string& file);

// The check both formats make of a Version object's text: the version, or InputError
// naming `file` (and the field's line, for IDF).
Version checked_version(const InputField& field, const std::string& file);

}  // namespace shadowgen::energyplus::detail
