#include "detail/lod.h"

#include <cmath>
#include <optional>

#include "shadowgen/model/number_text.h"

namespace shadowgen::cityjson::detail {

bool Lod::matches(const std::string& asked) const {
  if (!written_as_number) return asked == text;
  const std::optional<double> number = parse_number(asked);
  return number && *number == value;
}

Lod read_lod(const JsonValue& value) {
  Lod lod;
  if (value.describe() == "a number") {
    lod.value = value.number();
    lod.text = shortest(lod.value);
    lod.written_as_number = true;
  } else {
    lod.text = value.string();
    const std::optional<double> number = parse_number(lod.text);
    if (!number || !std::isfinite(*number)) {
      value.fail("'" + lod.text +
                 "' is not a level of detail: CityJSON writes a number such as \"2\" or \"2.2\"");
    }
    lod.value = *number;
  }
  if (!(lod.value >= 0.0)) value.fail("a level of detail is at least 0, found " + lod.text);
  return lod;
}

}  // namespace shadowgen::cityjson::detail
