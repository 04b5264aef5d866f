// Tests of shadowgen/model/number_range.h: the one rule for numbers out of their range,
// which the readers and the command line's options share.

#include "shadowgen/model/number_range.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace shadowgen {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(NumberRange, NanAndInfinitiesLieInNoRange) {
  EXPECT_FALSE(within(kNan, NumberRange{}));
  EXPECT_FALSE(within(kInf, NumberRange{}));
  EXPECT_FALSE(within(-kInf, at_least(0.0)));
  EXPECT_EQ(range_problem(kNan, at_least(0.0)), "is not a number");
  EXPECT_EQ(range_problem(kInf, at_least(0.0)), "must be finite");
  // Where the range has an upper bound, an infinity is past it, and the rule says so.
  const NumberRange latitude{.low = -90.0, .high = 90.0, .unit = " degrees"};
  EXPECT_EQ(range_problem(kInf, latitude), "must lie between -90 and 90 degrees");
  EXPECT_EQ(range_problem(-kInf, above(0.0)), "must be above 0");
}

// Bounds are written as they read back: the largest double as 1.7976931348623157e+308,
// never as its 309 digits (CLI11's ranges once wrote them so).
TEST(NumberRange, TheRuleWritesBoundsInTheirShortestForm) {
  EXPECT_EQ(range_rule(at_least(0.0)), "must be at least 0");
  EXPECT_EQ(range_rule(above(0.0, " hours")), "must be above 0 hours");
  EXPECT_EQ(range_rule({.low = 1e-6, .high = 180.0, .high_excluded = true, .unit = " degrees"}),
            "must be at least 1e-06 and below 180 degrees");
  EXPECT_EQ(range_rule(
                {.low = 0.0, .high = 1.0, .low_excluded = true, .high_excluded = true, .unit = ""}),
            "must lie strictly between 0 and 1");
  EXPECT_EQ(range_rule({.high = 1e300, .unit = ""}), "must be at most 1e+300");
  EXPECT_EQ(range_rule(whole_range(1, 1 << 20)), "must lie between 1 and 1048576");
  const double largest = std::numeric_limits<double>::max();
  EXPECT_EQ(range_rule({.low = 0.0, .high = largest, .high_excluded = true, .unit = ""}),
            "must be at least 0");
  EXPECT_EQ(range_rule({.low = 0.0, .high = 1.5e308, .unit = ""}),
            "must lie between 0 and 1.5e+308");
}

TEST(NumberRange, EndsAreInOrOutAsTheRangeSays) {
  const NumberRange fov{.low = 1e-6, .high = 180.0, .high_excluded = true, .unit = ""};
  EXPECT_TRUE(within(1e-6, fov));
  EXPECT_FALSE(within(std::nextafter(1e-6, 0.0), fov));
  EXPECT_TRUE(within(std::nextafter(180.0, 0.0), fov));
  EXPECT_FALSE(within(180.0, fov));
  EXPECT_FALSE(within(0.0, above(0.0)));
  EXPECT_TRUE(within(5e-324, above(0.0)));
  EXPECT_TRUE(within(0.0, at_least(0.0)));
  EXPECT_EQ(range_problem(90.0, {.low = -90.0, .high = 90.0, .unit = ""}), std::nullopt);
}

}  // namespace
}  // namespace shadowgen
