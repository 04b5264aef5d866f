#pragma once

// A file's objects made into the source model: every surface placed as EnergyPlus places
// it (placement.h, attached_shading.h), each window, door, glass door and tubular
// daylighting device also a hole in its base surface (its vertices taken along the base's
// normal into the base's plane, so a window set back in a reveal cuts the hole its
// projection makes), the faces in the objects' order (a fin's left, then right), ids the
// surface Names as written, and the site from Site:Location (docs/energyplus.md).

#include <string>
#include <vector>

#include "detail/input_object.h"
#include "shadowgen/model/source_model.h"

namespace shadowgen::energyplus::detail {

// InputError naming `file`, the object and the field for: a surface without a Name, two
// surfaces of one Name (compared ignoring case, as EnergyPlus and its shading schedule's
// columns compare them), a zone, base surface, window or door named and not there, a
// Surface Type EnergyPlus does not know, and every problem ObjectFields and read_frame
// find.
SourceModel build_model(const std::vector<InputObject>& objects, const std::string& file);

}  // namespace shadowgen::energyplus::detail
