// stable_length and stable_normalize: exact where the answer is exact, at any magnitude a
// double can hold, where glm::length overflows or underflows.

#include "hsr/vector_length.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace shadowgen::hsr {
namespace {

TEST(StableLength, IsExactOnPythagoreanTriplesAtEveryScale) {
  for (int e : {-1074 + 3, -1022, -600, -200, -1, 0, 1, 200, 600, 1020}) {
    const double s = std::ldexp(1.0, e);
    EXPECT_EQ(stable_length({3 * s, 4 * s, 0}), 5 * s) << "2^" << e;
    EXPECT_EQ(stable_length({0, -4 * s, 3 * s}), 5 * s) << "2^" << e;
    EXPECT_EQ(stable_length({2 * s, 3 * s, 6 * s}), 7 * s) << "2^" << e;
  }
}

TEST(StableLength, KeepsWhatGlmLengthLosesToOverflowAndUnderflow) {
  const glm::dvec3 huge(3e200, 4e200, 0);
  const glm::dvec3 tiny(3e-200, 4e-200, 0);
  ASSERT_TRUE(std::isinf(glm::length(huge)));
  ASSERT_EQ(glm::length(tiny), 0.0);
  EXPECT_DOUBLE_EQ(stable_length(huge), 5e200);
  EXPECT_DOUBLE_EQ(stable_length(tiny), 5e-200);
  const double largest = std::numeric_limits<double>::max();
  EXPECT_EQ(stable_length({largest, 0, 0}), largest);
  EXPECT_EQ(stable_length({0, 0, -std::numeric_limits<double>::denorm_min()}),
            std::numeric_limits<double>::denorm_min());
}

TEST(StableLength, OfTheZeroVectorIsZero) { EXPECT_EQ(stable_length(glm::dvec3(0.0)), 0.0); }

TEST(StableNormalize, GivesAUnitVectorAtAnyScale) {
  for (const glm::dvec3 v : {glm::dvec3(3e-300, -4e-300, 12e-300), glm::dvec3(1e300, 1e300, 1e300),
                             glm::dvec3(0, 0, -std::numeric_limits<double>::denorm_min()),
                             glm::dvec3(1e-320, 1e-320, 0)}) {
    const glm::dvec3 u = stable_normalize(v);
    EXPECT_NEAR(glm::length(u), 1.0, 4e-16) << v.x << ' ' << v.y << ' ' << v.z;
    EXPECT_GT(glm::dot(u, v), 0.0);
  }
  EXPECT_EQ(stable_normalize(glm::dvec3(3, -4, 12) * std::ldexp(1.0, -1000)),
            glm::dvec3(3, -4, 12) / 13.0);
  EXPECT_EQ(stable_normalize(glm::dvec3(0.0)), glm::dvec3(0.0));
}

}  // namespace
}  // namespace shadowgen::hsr
