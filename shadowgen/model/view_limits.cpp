#include "shadowgen/model/view_limits.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace shadowgen {
namespace {

// √ε: the sine below which up is along the sight (view_limits.h).
const double kAlongSightSine = std::sqrt(std::numeric_limits<double>::epsilon());

// `v` as a unit vector, scaled by its largest component first so that neither a tiny nor
// a huge vector underflows or overflows on the way. `v` is finite and not zero.
glm::dvec3 unit(const glm::dvec3& v) {
  const double largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  return glm::normalize(v / largest);
}

}  // namespace

NumberRange fov_range() {
  NumberRange range;
  range.low = kNarrowestFovDeg;
  range.high = kWidestFovDeg;
  range.high_excluded = true;
  range.unit = " degrees";
  return range;
}

NumberRange scale_range() {
  NumberRange range;
  range.low = kSmallestPixelsPerUnit;
  range.high = kLargestPixelsPerUnit;
  range.unit = " pixels per unit";
  return range;
}

bool along_sight(const glm::dvec3& sight, const glm::dvec3& up) {
  if (up == glm::dvec3(0.0)) return true;
  return glm::length(glm::cross(unit(sight), unit(up))) <= kAlongSightSine;
}

std::optional<std::string> up_problem(const glm::dvec3& sight, const glm::dvec3& up,
                                      const std::string& sight_name) {
  if (up == glm::dvec3(0.0)) return "must not be zero";
  if (along_sight(sight, up)) return "must not be parallel to the direction " + sight_name;
  return std::nullopt;
}

}  // namespace shadowgen
