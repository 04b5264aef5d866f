#pragma once

// Reading an EnergyPlus model, IDF or epJSON, versions 8.9 to 26.x, as the faces, origins
// and site of a scene's meshes[] entry (shadowgen/model/source_model.h;
// docs/energyplus.md):
//
//   SourceModel model = energyplus::read_energyplus("office.idf", {.strict = false});
//
// Every surface EnergyPlus makes of the file's geometry objects is a face, placed exactly
// as EnergyPlus places it (GlobalGeometryRules, zone origins and relative north, the
// building's north axis, the simplified rectangular objects, overhangs and fins), in world
// coordinates with +y true north, its front side the surface's outside. Its id is the
// surface Name as written (a fin's two: "<Name> Left", "<Name> Right"); windows, doors and
// glass doors are also holes in their base surface. Other objects are skipped.
//
// The format is told by content: epJSON when the first character that is not blank (after
// a UTF-8 byte order mark) is '{', IDF otherwise.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "shadowgen/model/source_model.h"

namespace shadowgen::energyplus {

// The most bytes an EnergyPlus file is read to (256 MiB: the largest real models are tens
// of megabytes); a larger file, or a stream that goes on, is refused.
inline constexpr std::size_t kLargestEnergyPlusFile = std::size_t{256} << 20;

// Every error is an InputError naming the file (and, for IDF, the line), the object's class
// and Name and the field: a file that cannot be read, a number that does not read or is
// not finite, a vertex count that does not match, fewer than 3 vertices, a zone or base
// surface named and not there, two surfaces of one Name, a Version outside 8.9 to 26.x.
SourceModel read_energyplus(const std::filesystem::path& file, const SourceOptions& options);

// The same from the file's text; `file` names it in messages.
SourceModel parse_energyplus(std::string_view text, const std::string& file,
                             const SourceOptions& options);

}  // namespace shadowgen::energyplus
