// The sun-hours report (shadowgen/output/sun_hours_report.h) against regions made by hand.

#include "shadowgen/output/sun_hours_report.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

using test::sun_path_by_hand;

TEST(SunHoursReport, MeanHoursAndTheAreaWithAtLeastEachThreshold) {
  const std::vector<double> thresholds{0, 1.5, 2, 3};
  const std::vector<SunHoursRow> rows = sun_hours_rows(sun_path_by_hand(), thresholds);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].area, 4.0);
  EXPECT_EQ(rows[0].mean_hours, (1.5 * 2 + 2.0) / 4.0);
  EXPECT_EQ(rows[0].min_hours, 0.0);
  EXPECT_EQ(rows[0].max_hours, 2.0);
  EXPECT_EQ(rows[0].area_at_least, (std::vector<double>{4, 3, 1, 0}));
  EXPECT_EQ(sun_hours_csv(sun_path_by_hand(), thresholds),
            "face_id,sun_path,area,mean_sun_hours,min_sun_hours,max_sun_hours,"
            "area_at_least_0h,area_at_least_1.5h,area_at_least_2h,area_at_least_3h\n"
            "g,p,4,1.25,0,2,4,3,1,0\n");
}

TEST(SunHoursReport, ADatabaseWithoutSunPathsOrABadThresholdIsRefused) {
  ShadowedScene none = sun_path_by_hand();
  none.sun_paths.clear();
  try {
    (void)sun_hours_csv(none, std::vector<double>{2});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.json: has no sun path (a `sun` light with from, to and step_min) to report "
              "sun hours of");
  }
  EXPECT_THROW((void)sun_hours_rows(sun_path_by_hand(), std::vector<double>{-1}),
               std::invalid_argument);
}

}  // namespace
}  // namespace shadowgen
