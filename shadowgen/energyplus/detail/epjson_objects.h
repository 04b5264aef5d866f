#pragma once

// The objects of an epJSON file that this room reads (object_classes.h), read with the
// project's JSON reader (duplicate keys refused, numbers finite): the top level maps a
// class to its objects, each keyed by its Name, each mapping field names to values, the
// vertices an array "vertices" of {vertex_x_coordinate, ...} or the fixed fields
// vertex_1_x_coordinate ... of FenestrationSurface:Detailed. Other classes are passed
// over; a key a read class does not define draws a warning (under strict, an error).
// Objects come in the order of their `idf_order` (what EnergyPlus's converter writes from
// an IDF's order) where they give one, then in the file's key order.

#include <string>
#include <string_view>
#include <vector>

#include "detail/input_object.h"

namespace shadowgen::energyplus::detail {

// InputError naming `file` (and the JSON path) for text that is not JSON or not the
// form above, and for a Version object out of range; `warnings` gets the unknown keys.
std::vector<InputObject> epjson_objects(std::string_view text, const std::string& file, bool strict,
                                        std::vector<std::string>& warnings);

}  // namespace shadowgen::energyplus::detail
