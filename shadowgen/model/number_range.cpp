#include "shadowgen/model/number_range.h"

#include <cmath>
#include <utility>

#include "shadowgen/model/number_text.h"

namespace shadowgen {
namespace {

constexpr double kLargest = std::numeric_limits<double>::max();

bool bounded_below(const NumberRange& range) { return range.low > -kLargest; }
bool bounded_above(const NumberRange& range) { return range.high < kLargest; }

// A bound as it reads back: a whole number below 2^53 in all its digits ("1000000000",
// which shortest() writes "1e+09"), any other in its shortest form ("1e-06", "1e+100").
std::string bound_text(double bound) {
  constexpr double kExactWhole = 9007199254740992.0;  // 2^53
  if (std::fabs(bound) < kExactWhole && bound == std::trunc(bound)) {
    return std::to_string(static_cast<std::int64_t>(bound));
  }
  return shortest(bound);
}

}  // namespace

NumberRange at_least(double low, std::string unit) {
  NumberRange range;
  range.low = low;
  range.unit = std::move(unit);
  return range;
}

NumberRange above(double low, std::string unit) {
  NumberRange range = at_least(low, std::move(unit));
  range.low_excluded = true;
  return range;
}

std::string interval_text(const NumberRange& range) {
  const std::string low = bound_text(range.low);
  if (!bounded_above(range)) return (range.low_excluded ? "> " : ">= ") + low;
  return (range.low_excluded ? "(" : "[") + low + ", " + bound_text(range.high) +
         (range.high_excluded ? ")" : "]");
}

bool within(double value, const NumberRange& range) {
  if (!std::isfinite(value)) return false;
  if (range.low_excluded ? !(value > range.low) : !(value >= range.low)) return false;
  return range.high_excluded ? value < range.high : value <= range.high;
}

std::string range_rule(const NumberRange& range) {
  const std::string low = bound_text(range.low), high = bound_text(range.high);
  if (!bounded_above(range)) {
    return (range.low_excluded ? "must be above " : "must be at least ") + low + range.unit;
  }
  if (!bounded_below(range)) {
    return (range.high_excluded ? "must be below " : "must be at most ") + high + range.unit;
  }
  if (!range.low_excluded && !range.high_excluded) {
    return "must lie between " + low + " and " + high + range.unit;
  }
  if (range.low_excluded && range.high_excluded) {
    return "must lie strictly between " + low + " and " + high + range.unit;
  }
  return (range.low_excluded ? "must be above " : "must be at least ") + low +
         (range.high_excluded ? " and below " : " and at most ") + high + range.unit;
}

std::optional<std::string> range_problem(double value, const NumberRange& range) {
  if (within(value, range)) return std::nullopt;
  if (std::isnan(value)) return "is not a number";
  if (std::isinf(value) && (value > 0.0 ? !bounded_above(range) : !bounded_below(range))) {
    return "must be finite";
  }
  return range_rule(range);
}

NumberRange whole_range(std::int64_t low, std::int64_t high) {
  NumberRange range;
  range.low = static_cast<double>(low);
  range.high = static_cast<double>(high);
  return range;
}

}  // namespace shadowgen
