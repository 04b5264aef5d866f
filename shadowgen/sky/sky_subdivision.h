#pragma once

// A sky subdivision as the command line names it (--sky): "tregenza" (Reinhart's MF:1) or
// "reinhart:N", N a whole number from 1 to kMostReinhartSubdivisions (sky_patches.h).

#include <optional>
#include <string>
#include <string_view>

namespace shadowgen::sky {

// N of the subdivision `name` names; std::nullopt for any other text.
std::optional<int> subdivisions_named(std::string_view name);

// The name of MF:`subdivisions`: "tregenza" for 1, "reinhart:N" otherwise.
std::string subdivision_name(int subdivisions);

}  // namespace shadowgen::sky
