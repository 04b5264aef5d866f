#pragma once

// --sky, which `report` and `compare` share: a sky subdivision by name
// (shadowgen/sky/sky_subdivision.h), tregenza or reinhart:N, refused saying what it takes.

#include <CLI/CLI.hpp>
#include <string>

namespace shadowgen::cli {

// --sky on `command`: sets `subdivisions` to the subdivision named (Reinhart's MF:N) and
// `given` to true; `help` says what it does there.
CLI::Option* add_sky_option(CLI::App& command, int& subdivisions, bool& given,
                            const std::string& help);

}  // namespace shadowgen::cli
