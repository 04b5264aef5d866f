#pragma once

// The EnergyPlus versions read: 8.9 to 26.x. The field positions of the objects read
// (object_classes.h) are those of 8.9, of 9.0 to 9.5 and of 9.6 on; releases after 9.6
// (numbered 22.1, 22.2, 23.1, ... by year) are read with 9.6's field lists, which they
// have not moved as far as this reader knows (docs/energyplus.md, "Versions").

#include <optional>
#include <string>
#include <string_view>

#include "detail/object_classes.h"

namespace shadowgen::energyplus::detail {

inline constexpr Version kOldestVersion{8, 9};
inline constexpr Version kNewestVersion{26, 2};
// A file without a Version object: epJSON names its fields, so none is needed there.
inline constexpr Version kUnstatedVersion = kNewestVersion;

// "9.6", "9.6.0", "24.1.0" as a version; nullopt for text that is not one.
std::optional<Version> parse_version(std::string_view text);

// "9.6".
std::string version_text(Version version);

}  // namespace shadowgen::energyplus::detail
