#include "detail/instant_time.h"

#include <optional>

#include "shadowgen/model/input_error.h"

namespace shadowgen::output::detail {

sun::CivilTime instant_time(const Light& light, const SunPathHours& path,
                            const std::string& weather_file) {
  const std::optional<sun::CivilTime> time =
      light.sun ? sun::parse_civil_time(light.sun->time) : std::nullopt;
  if (!time) {
    throw InputError(weather_file, "",
                     "light '" + light.id + "' of sun path '" + path.id +
                         "' has no instant to read the weather at");
  }
  return *time;
}

}  // namespace shadowgen::output::detail
