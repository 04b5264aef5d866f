#include "cli/sky_option.h"

#include "shadowgen/sky/sky_subdivision.h"

namespace shadowgen::cli {

CLI::Option* add_sky_option(CLI::App& command, int& subdivisions, bool& given,
                            const std::string& help) {
  return command
      .add_option_function<std::string>(
          "--sky",
          [&subdivisions, &given](const std::string& name) {
            subdivisions = *sky::subdivisions_named(name);
            given = true;
          },
          help)
      ->check(CLI::Validator(
          [](std::string& name) -> std::string {
            return sky::subdivisions_named(name)
                       ? ""
                       : "'" + name + "' names no sky: tregenza or reinhart:N, N from 1 to 64";
          },
          "tregenza|reinhart:N", "sky"));
}

}  // namespace shadowgen::cli
