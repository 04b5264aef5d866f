// Numbers as text: round-trip shortest forms, and readable forms given whole at any
// magnitude (a fixed form of a huge number once came back as a buffer of NUL bytes).

#include "shadowgen/model/number_text.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <system_error>

namespace shadowgen {
namespace {

// The double a text reads as (std::stod refuses subnormal values).
double parsed(const std::string& text) {
  double value = 0.0;
  const std::from_chars_result r = std::from_chars(text.data(), text.data() + text.size(), value);
  EXPECT_EQ(r.ec, std::errc()) << text;
  EXPECT_EQ(r.ptr, text.data() + text.size()) << text;
  return value;
}

TEST(NumberText, ShortestReadsBackToTheSameDouble) {
  EXPECT_EQ(shortest(0.1), "0.1");
  EXPECT_EQ(shortest(28.0), "28");
  EXPECT_EQ(shortest(-0.0), "-0");
  EXPECT_EQ(shortest(1.5e101), "1.5e+101");
  for (const double v : {1.0 / 3.0, std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::denorm_min(), -1e-300, 1e8 + 0.1}) {
    EXPECT_EQ(parsed(shortest(v)), v) << shortest(v);
  }
  std::string out = "x=";
  append_shortest(out, 2.5);
  EXPECT_EQ(out, "x=2.5");
}

TEST(NumberText, GeneralHasTheDigitsAskedFor) {
  EXPECT_EQ(number_text(1.23456789e-7, std::chars_format::general, 3), "1.23e-07");
  EXPECT_EQ(number_text(1e200, std::chars_format::general, 6), "1e+200");
  EXPECT_EQ(number_text(0.5, std::chars_format::general, 17), "0.5");
}

TEST(NumberText, FixedFormsOfHugeNumbersComeWhole) {
  const std::string text = number_text(1e300, std::chars_format::fixed, 4);
  ASSERT_EQ(text.size(), 301u + 5u) << text;  // 301 digits, the point and 4 decimals
  EXPECT_EQ(text.find('\0'), std::string::npos);
  EXPECT_EQ(text.substr(0, 5), "10000");
  EXPECT_EQ(text.substr(text.size() - 5), ".0000");
  EXPECT_EQ(parsed(text), 1e300);
  const std::string largest =
      number_text(-std::numeric_limits<double>::max(), std::chars_format::fixed, 1);
  EXPECT_EQ(largest.size(), 1u + 309u + 2u);
  EXPECT_EQ(parsed(largest), -std::numeric_limits<double>::max());
  EXPECT_EQ(number_text(0.83673, std::chars_format::fixed, 4), "0.8367");
}

}  // namespace
}  // namespace shadowgen
