// The sun-hours table (shadowgen/output/sun_hours_table.h): the BRE 209 line's wording, its
// verdict at exactly half the area and just under it, the days of a path, and the whole
// table to the byte on sums made by hand.

#include "shadowgen/output/sun_hours_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

TEST(SunTestLine, SaysTheShareTheAreaTheThresholdTheDayAndTheVerdict) {
  EXPECT_EQ(sun_test_line("garden", 412, 361.3, 2, "on 21 March"),
            "garden: 87.7 % of 412 m² gets ≥ 2 h on 21 March: passes");
  EXPECT_EQ(sun_test_line("yard", 41.26, 10, 1.5, "on 21 March"),
            "yard: 24.2 % of 41.3 m² gets ≥ 1.5 h on 21 March: fails");
  EXPECT_EQ(sun_test_line("bed", 0.5, 0.5, 2, "on 21 March"),
            "bed: 100.0 % of 0.5 m² gets ≥ 2 h on 21 March: passes");
  EXPECT_EQ(sun_test_line("path", 0, 0, 2, "on 21 March"), "path: no area");
}

TEST(SunTestLine, HalfTheAreaPassesAndAFailingShareNeverReadsAsHalf) {
  EXPECT_EQ(sun_test_line("garden", 412, 206, 2, "on 21 March"),
            "garden: 50.0 % of 412 m² gets ≥ 2 h on 21 March: passes");
  EXPECT_EQ(sun_test_line("garden", 412, 205.9, 2, "on 21 March"),
            "garden: 49.98 % of 412 m² gets ≥ 2 h on 21 March: fails");
  EXPECT_EQ(sun_test_line("garden", 100, 49.999, 2, "on 21 March"),
            "garden: 49.999 % of 100 m² gets ≥ 2 h on 21 March: fails");
  const std::string hair = sun_test_line("garden", 412, std::nextafter(206.0, 0.0), 2, "");
  EXPECT_EQ(hair.substr(0, 12), "garden: 49.9") << hair;
  EXPECT_EQ(hair.substr(hair.size() - 7), ": fails") << hair;
}

TEST(SunPathDays, OneDayOrASpanYearsWhereTheyDiffer) {
  EXPECT_EQ(sun_path_days("2026-03-21T08:00", "2026-03-21T16:00"), "on 21 March");
  EXPECT_EQ(sun_path_days("2026-03-20T00:00", "2026-03-22T23:59"), "from 20 March to 22 March");
  EXPECT_EQ(sun_path_days("2026-12-31T00:00", "2027-01-01T12:00"),
            "from 31 December 2026 to 1 January 2027");
}

TEST(SunHoursTable, OneLinePerFaceOrGroupAndThreshold) {
  const ShadowedScene s = test::sun_path_by_hand();  // g: 4 × 1, 2 h on 1, 1.5 h on 2 more
  const std::string head =
      "sun path 'p': 21 March 2026 10:00 to 13:00, every 30 min\n"
      "an area passes when at least 50 % of it gets at least the hours shown (BRE 209, 2022, "
      "section 3.3: 2 h on 21 March)\n";
  EXPECT_EQ(sun_hours_table(s, std::vector<double>{2, 1.5}),
            head +
                "g: 25.0 % of 4 m² gets ≥ 2 h on 21 March: fails\n"
                "g: 75.0 % of 4 m² gets ≥ 1.5 h on 21 March: passes\n");
  const std::vector<groups::FaceGroup> groups{{"lawn", {0}}};
  EXPECT_EQ(sun_hours_table(s, std::vector<double>{2}, groups),
            head + "lawn: 25.0 % of 4 m² gets ≥ 2 h on 21 March: fails\n");
}

}  // namespace
}  // namespace shadowgen
