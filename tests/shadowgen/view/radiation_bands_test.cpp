#include "shadowgen/view/radiation_bands.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowgen/output/hour_bands.h"

namespace shadowgen {
namespace {

TEST(RadiationBands, TheNarrowestRoundWidthGivingAtMostTenBands) {
  // 4.88 kWh/m²: 0.2 would give 25 bands, 0.5 gives 10.
  const RadiationBands day = radiation_bands("march21", 4.88);
  EXPECT_EQ(day.width, 0.5);
  ASSERT_EQ(day.bands.size(), 10u);
  EXPECT_EQ(day.bands.front().label, "0\u20130.5 kWh/m\u00b2");
  EXPECT_EQ(day.bands.back().label, "4.5\u20135 kWh/m\u00b2");
  EXPECT_EQ(day.bands[3].from, 1.5);
  EXPECT_EQ(day.bands[3].to, 2.0);
  // A year on a roof: 1,040 kWh/m² in bands of 200, the last holding its upper edge.
  const RadiationBands year = radiation_bands("year", 1040.0);
  EXPECT_EQ(year.width, 200.0);
  ASSERT_EQ(year.bands.size(), 6u);
  EXPECT_EQ(year.bands.back().label, "1000\u20131200 kWh/m\u00b2");
  // 1,000 exactly: ten bands of 100, the last holding 1,000.
  const RadiationBands edge = radiation_bands("edge", 1000.0);
  EXPECT_EQ(edge.width, 100.0);
  ASSERT_EQ(edge.bands.size(), 10u);
  EXPECT_EQ(edge.band_of(1000.0), 9u);
  // Nothing at all: one band.
  EXPECT_EQ(radiation_bands("night", 0.0).bands.size(), 1u);
}

TEST(RadiationBands, ValuesFallInTheBandWhoseLowerEdgeTheyReach) {
  const RadiationBands bands = radiation_bands("march21", 4.88);
  EXPECT_EQ(bands.band_of(0.0), 0u);
  EXPECT_EQ(bands.band_of(0.4999), 0u);
  EXPECT_EQ(bands.band_of(0.5), 1u);
  EXPECT_EQ(bands.band_of(4.88), 9u);
  EXPECT_EQ(bands.band_of(5.0), 9u);
  EXPECT_EQ(bands.band_of(-1.0), 0u);
}

TEST(RadiationBands, ColoursAreTheSunHoursRampAtEachBandsMiddle) {
  const RadiationBands bands = radiation_bands("p", 4.0);  // 8 bands of 0.5
  ASSERT_EQ(bands.bands.size(), 8u);
  for (std::size_t i = 0; i < bands.bands.size(); ++i) {
    const glm::dvec3 expected = sun_hours_ramp((static_cast<double>(i) + 0.5) / 8.0);
    EXPECT_EQ(bands.bands[i].colour, expected) << i;
  }
  EXPECT_EQ(bands.caption(),
            (std::vector<std::string>{"Irradiation, kWh/m\u00b2: p", "direct + diffuse + ground"}));
}

TEST(RadiationBands, ANegativeOrNonFiniteMostIsRefused) {
  EXPECT_THROW(radiation_bands("p", -1.0), std::invalid_argument);
  EXPECT_THROW(radiation_bands("p", std::numeric_limits<double>::infinity()),
               std::invalid_argument);
}

}  // namespace
}  // namespace shadowgen
