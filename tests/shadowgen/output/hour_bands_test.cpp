// Hour bands of sun-hours maps (shadowgen/output/hour_bands.h): the default edges for paths
// of various steps and lengths, edges given, labels and names, colours sampled at the
// centre of the hours a band can hold, and the ramp.

#include "shadowgen/output/hour_bands.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

// "#rrggbb", each channel round(255 × v), as the SVG writer writes colours.
std::string hex(const glm::dvec3& colour) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x",
                static_cast<unsigned>(std::lround(255 * colour.r)),
                static_cast<unsigned>(std::lround(255 * colour.g)),
                static_cast<unsigned>(std::lround(255 * colour.b)));
  return text;
}

// A path "p" of `instants` instants `step_min` minutes apart (its regions do not matter
// here).
SunPathHours path_of(int step_min, std::size_t instants) {
  SunPathHours path = test::sun_path_by_hand().sun_paths.at(0);
  path.step_min = step_min;
  path.instants.assign(instants, 0);
  return path;
}

std::vector<std::string> labels(const HourBands& bands) {
  std::vector<std::string> out;
  for (const HourBand& band : bands.bands) out.push_back(band.label);
  return out;
}

std::vector<std::string> names(const HourBands& bands) {
  std::vector<std::string> out;
  for (const HourBand& band : bands.bands) out.push_back(band.name);
  return out;
}

std::vector<std::string> colours(const HourBands& bands) {
  std::vector<std::string> out;
  for (const HourBand& band : bands.bands) out.push_back(hex(band.colour));
  return out;
}

TEST(HourBands, DefaultEdgesAreRoundStepsNoFinerThanThePathsStepAtMostTwelveBands) {
  // 21 March, 08:00 to 16:00 every two hours: one band per number of instants.
  EXPECT_EQ(default_band_edges(120, 5), (std::vector<double>{2, 4, 6, 8, 10}));
  // 08:00 to 16:00 every 10 minutes: 8 h 10 min at most; whole hours give 9 bands.
  EXPECT_EQ(default_band_edges(10, 49), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}));
  // 13 hours: whole hours would give 14 bands, so two-hour ones.
  EXPECT_EQ(default_band_edges(60, 13), (std::vector<double>{2, 4, 6, 8, 10, 12}));
  // 8 h 15 min every 15 minutes: quarter and half hours give too many.
  EXPECT_EQ(default_band_edges(15, 33), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}));
  // Half an hour every minute: 0.05 h (3 minutes), each edge the double nearest its
  // decimal (one division), so that labels read "0.15", not "0.15000000000000002".
  EXPECT_EQ(default_band_edges(1, 30),
            (std::vector<double>{0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5}));
  // A year every hour: 50-day bands.
  EXPECT_EQ(default_band_edges(60, 8760),
            (std::vector<double>{1200, 2400, 3600, 4800, 6000, 7200, 8400}));
  // No band narrower than the step: one 7-minute instant is one band, as is no instant.
  EXPECT_EQ(default_band_edges(7, 1), std::vector<double>{});
  EXPECT_EQ(default_band_edges(30, 0), std::vector<double>{});
  EXPECT_THROW((void)default_band_edges(0, 3), std::invalid_argument);
}

TEST(HourBands, BandsLabelsAndNamesFromTheEdges) {
  const HourBands bands = hour_bands(path_of(120, 5));
  EXPECT_EQ(bands.path_id, "p");
  EXPECT_EQ(bands.step_min, 120);
  EXPECT_EQ(bands.instants, 5u);
  EXPECT_EQ(bands.most_hours, 10.0);
  ASSERT_EQ(bands.bands.size(), 6u);
  EXPECT_EQ(bands.bands[0].from, 0.0);
  EXPECT_EQ(bands.bands[0].to, 2.0);
  EXPECT_EQ(bands.bands[4].from, 8.0);
  EXPECT_EQ(bands.bands[4].to, 10.0);
  EXPECT_EQ(bands.bands[5].from, 10.0);
  EXPECT_EQ(bands.bands[5].to, 10.0);
  EXPECT_EQ(labels(bands), (std::vector<std::string>{"0\u20132 h", "2\u20134 h", "4\u20136 h",
                                                     "6\u20138 h", "8\u201310 h", "\u2265 10 h"}));
  EXPECT_EQ(names(bands),
            (std::vector<std::string>{"0-2h", "2-4h", "4-6h", "6-8h", "8-10h", "10h+"}));
  EXPECT_EQ(bands.caption(),
            (std::vector<std::string>{"Sun hours: p", "5 instants, every 120 min"}));
  EXPECT_EQ(hour_bands(path_of(30, 1)).caption()[1], "1 instant, every 30 min");
}

TEST(HourBands, AnEdgeBeginsItsBand) {
  const HourBands bands = hour_bands(path_of(30, 4));  // edges 0.5, 1, 1.5, 2
  ASSERT_EQ(bands.bands.size(), 5u);
  EXPECT_EQ(bands.band_of(0.0), 0u);
  EXPECT_EQ(bands.band_of(0.49), 0u);
  EXPECT_EQ(bands.band_of(0.5), 1u);
  EXPECT_EQ(bands.band_of(1.5), 3u);
  EXPECT_EQ(bands.band_of(2.0), 4u);
  EXPECT_EQ(bands.band_of(3.0), 4u);   // beyond the most: the last
  EXPECT_EQ(bands.band_of(-1.0), 0u);  // below 0: the first
  // The database's hours (count × step_min / 60) fall on the edges they equal, as typed.
  const std::vector<double> edges{0.3, 0.6, 0.9, 1.2, 1.5, 1.8, 2.1, 2.4, 2.7, 3};
  const HourBands tenths = hour_bands(path_of(6, 30), edges);
  for (std::size_t count = 0; count <= 30; ++count) {
    const double hours = static_cast<double>(count) * 6 / 60.0;
    EXPECT_EQ(tenths.band_of(hours), count / 3) << hours;
  }
}

TEST(HourBands, ColoursAreTheRampAtTheCentreOfTheHoursABandCanHold) {
  // Eight hours in two-hour steps: the bands hold 0, 2, 4, 6 and 8 hours, so their colours
  // are the ramp at 0, 1/4, 1/2, 3/4 and 1: viridis's control colours 0, 2, 4, 6 and 8.
  EXPECT_EQ(colours(hour_bands(path_of(120, 4))),
            (std::vector<std::string>{"#440154", "#3b528b", "#21918c", "#5ec962", "#fde725"}));
  // Edges given: [0, 0.5) holds 0; [0.5, 1.75) holds 0.5, 1 and 1.5 (centre 1 of 2 hours);
  // [1.75, 2] holds 2.
  const std::vector<double> edges{0.5, 1.75};
  const HourBands given = hour_bands(path_of(30, 4), edges);
  EXPECT_EQ(labels(given),
            (std::vector<std::string>{"0\u20130.5 h", "0.5\u20131.75 h", "\u2265 1.75 h"}));
  EXPECT_EQ(names(given), (std::vector<std::string>{"0-0.5h", "0.5-1.75h", "1.75h+"}));
  EXPECT_EQ(colours(given), (std::vector<std::string>{"#440154", "#21918c", "#fde725"}));
  // A band that can hold no hours of the path gets the ramp at its own midpoint.
  const std::vector<double> narrow{0.25, 0.4};
  const HourBands gap = hour_bands(path_of(30, 4), narrow);
  EXPECT_EQ(gap.bands[1].colour, sun_hours_ramp(0.325 / 2.0));
  EXPECT_EQ(gap.bands[2].colour, sun_hours_ramp(((0.5 + 2.0) / 2.0) / 2.0));
}

TEST(HourBands, EdgesThatDoNotFitThePathAreRefused) {
  const SunPathHours path = path_of(30, 4);  // 2 hours at most
  auto problem = [&path](std::vector<double> edges) -> std::string {
    try {
      (void)hour_bands(path, edges);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(problem({0}), "a band edge must be a finite number of hours above 0, not 0");
  EXPECT_EQ(problem({-1}), "a band edge must be a finite number of hours above 0, not -1");
  EXPECT_EQ(problem({std::numeric_limits<double>::quiet_NaN()}),
            "a band edge must be a finite number of hours above 0, not nan");
  EXPECT_EQ(problem({1, 1}), "band edges must be in increasing order (1 before 1)");
  EXPECT_EQ(problem({1.5, 0.5}), "band edges must be in increasing order (1.5 before 0.5)");
  EXPECT_EQ(problem({1, 2.5}),
            "the band edge 2.5 is above the 2 h that sun path 'p' gives at most");
  EXPECT_EQ(problem({2}), "no error");  // a last band of sun at every instant
}

TEST(HourBands, TheRampIsViridisAndGrowsLighter) {
  EXPECT_EQ(hex(sun_hours_ramp(0.0)), "#440154");
  EXPECT_EQ(hex(sun_hours_ramp(0.5)), "#21918c");
  EXPECT_EQ(hex(sun_hours_ramp(1.0)), "#fde725");
  EXPECT_EQ(hex(sun_hours_ramp(-1.0)), "#440154");
  EXPECT_EQ(hex(sun_hours_ramp(7.0)), "#fde725");
  EXPECT_EQ(hex(sun_hours_ramp(std::numeric_limits<double>::quiet_NaN())), "#440154");
  // Relative luminance (sRGB decoded, Rec. 709 weights) rises all the way: more sun reads
  // lighter, in colour and in grey.
  auto luminance = [](const glm::dvec3& c) {
    auto linear = [](double v) {
      return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
  };
  double previous = -1.0;
  for (int i = 0; i <= 64; ++i) {
    const double y = luminance(sun_hours_ramp(i / 64.0));
    EXPECT_GT(y, previous) << i;
    previous = y;
  }
}

}  // namespace
}  // namespace shadowgen
