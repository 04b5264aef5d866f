#pragma once

// The one home of the command line's numbers: every numeric option of every subcommand
// is checked by a validator made here, at parse time, so that a number out of its range,
// NaN, an infinity or text that is not a number is a usage error (exit 2) before any work,
// with a message that names the option and writes its bounds as they read back
// ("--fov: 1e-200 must be at least 1e-06 and below 180 degrees"). The ranges themselves
// are shadowgen's (NumberRange, shadowgen/model/number_range.h), shared with the readers.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <string_view>

#include "shadowgen/model/number_range.h"

namespace shadowgen::cli {

// A decimal number within `range` (std::from_chars: no hexadecimal, independent of the
// locale).
CLI::Validator number_in(const NumberRange& range);

// A whole number from `low` to `high`, both included.
CLI::Validator whole_number_in(std::int64_t low, std::int64_t high);

// `text` as a whole number from `low` to `high`; nullopt when it is not one (for options
// that carry numbers inside other text: K/N, rays:SAMPLES).
std::optional<std::int64_t> whole_number_within(std::string_view text, std::int64_t low,
                                                std::int64_t high);

// "X,Y,Z" as three finite numbers; nullopt when it is not.
std::optional<glm::dvec3> parse_triple(std::string_view text);

// X,Y,Z: three finite numbers (a direction).
CLI::Validator triple();

// X,Y,Z: a point of the scene, its coordinates within the supported range
// (shadowgen/model/coordinate_range.h).
CLI::Validator point();

}  // namespace shadowgen::cli
