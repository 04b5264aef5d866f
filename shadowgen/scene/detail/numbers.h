#pragma once

// Small number helpers the scene room's checks share.

#include <cmath>
#include <glm/vec3.hpp>
#include <string>

#include "shadowgen/model/number_text.h"

namespace shadowgen::scene::detail {

// `value` with `digits` significant digits, for messages ("1.24e-07").
inline std::string short_number(double value, int digits) {
  return number_text(value, std::chars_format::general, digits);
}

inline bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace shadowgen::scene::detail
