#pragma once

// The relative error the suites measure areas and sums with, written once.

#include <cmath>

namespace shadowgen::test {

// |actual − expected| / |expected|, or |actual| where `expected` is 0.
inline double relative_error(double actual, double expected) {
  if (expected == 0.0) return std::abs(actual);
  return std::abs(actual - expected) / std::abs(expected);
}

}  // namespace shadowgen::test
