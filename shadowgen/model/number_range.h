#pragma once

// The range a number of the input may take, and the one message that says a number is
// out of it, shared by the readers (a site's values, a view's field of view) and the
// command line's numeric options (cli/number_options.h), so that every number shadowgen
// takes is checked, and refused, the same way.
//
// A number within a range is finite: NaN and the infinities lie in no range. Bounds are
// written as they read back ("1e-06", "180", "1000000000", "1e+100"), never as hundreds
// of digits.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace shadowgen {

struct NumberRange {
  double low = -std::numeric_limits<double>::max();
  double high = std::numeric_limits<double>::max();
  bool low_excluded = false;   // low itself lies outside
  bool high_excluded = false;  // high itself lies outside
  std::string unit;            // " degrees", " m", "": written after the bounds
};

// A range with no upper bound but the largest finite double: "at least `low`".
NumberRange at_least(double low, std::string unit = "");
// The same with `low` itself outside: "above `low`".
NumberRange above(double low, std::string unit = "");

// Whether `value` is finite and within `range`.
bool within(double value, const NumberRange& range);

// What `range` asks of a number: "must lie between -90 and 90 degrees", "must be at
// least 1e-06 and below 180 degrees", "must be above 0" (a number with no upper bound
// but the largest double is only said to be finite where that matters).
std::string range_rule(const NumberRange& range);

// The range in brief, as help texts show it: "[1e-06, 180)", ">= 0", "(0, 1]".
std::string interval_text(const NumberRange& range);

// Nothing when `value` is within `range`; otherwise what is wrong with it: "is not a
// number" (NaN), "must be finite" (an infinity where the range is bounded), or the rule.
std::optional<std::string> range_problem(double value, const NumberRange& range);

// The whole numbers from `low` to `high`, both included, as a NumberRange (exact for
// magnitudes up to 2^53).
NumberRange whole_range(std::int64_t low, std::int64_t high);

}  // namespace shadowgen
