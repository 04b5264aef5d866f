// `shadowgen report --format sky`: the sky view factor of every face, from the sky's
// patches as lights, end to end.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

// An open roof 10 × 10 at z = 3, a wall 10 long and 2 high 20 south of it, and a
// street canyon of width 2 and height 2 (H/W 1), 400 long, with a small face in the middle
// of its floor (which sees cos(atan 2) of the sky). The scene's own sun is not generated.
const std::string kStreet = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "roof", "outer": [[100,0,3],[110,0,3],[110,10,3],[100,10,3]]},
    {"id": "wall", "outer": [[100,-20,0],[110,-20,0],[110,-20,2],[100,-20,2]]},
    {"id": "street", "outer": [[-0.01,-0.01,0],[0.01,-0.01,0],[0.01,0.01,0],[-0.01,0.01,0]]},
    {"id": "south", "outer": [[-200,-1,0],[200,-1,0],[200,-1,2],[-200,-1,2]]},
    {"id": "north", "outer": [[200,1,0],[-200,1,0],[-200,1,2],[200,1,2]]}
  ],
  "lights": [{"id": "noon", "type": "directional", "direction": [0,0,-1]}]
})";

class SkyCli : public CliFolderTest<> {
 protected:
  SkyCli() : CliFolderTest("sky-cli") {}
};

TEST_F(SkyCli, SkyViewFactorsMeetTheirClosedForms) {
  const fs::path scene = write("street.json", kStreet);
  const Outcome sky = run({"report", scene.string(), "--format", "sky"});
  ASSERT_EQ(sky.code, 0) << sky.err;
  EXPECT_EQ(sky.err, "");
  const auto rows = csv_rows(sky.out);
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0],
            (std::vector<std::string>{"face_id", "area", "sky_view_factor", "ground_view_factor"}));
  EXPECT_EQ(rows[1][0], "roof");
  EXPECT_EQ(rows[1][1], "100");
  EXPECT_NEAR(std::stod(rows[1][2]), 1.0, 1e-12);
  EXPECT_EQ(rows[1][3], "0");
  EXPECT_EQ(rows[2][0], "wall");
  EXPECT_NEAR(std::stod(rows[2][2]), 0.5, 1e-4);  // the quadrature's bound
  EXPECT_EQ(rows[2][3], "0.5");
  EXPECT_EQ(rows[3][0], "street");
  EXPECT_NEAR(std::stod(rows[3][2]) / std::cos(std::atan(2.0)), 1.0, 0.005);
}

TEST_F(SkyCli, ADatabaseThreadsAndSubdivisionsGiveTheSameRows) {
  const fs::path scene = write("street.json", kStreet);
  const fs::path db = dir_ / "street.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome one =
      run({"report", scene.string(), "--format", "sky", "--sky", "reinhart:2", "--threads", "1"});
  ASSERT_EQ(one.code, 0) << one.err;
  const Outcome two =
      run({"report", db.string(), "--format", "sky", "--sky", "reinhart:2", "--threads", "2"});
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_EQ(one.out, two.out);
  const Outcome tregenza = run({"report", scene.string(), "--format", "sky", "--sky", "tregenza"});
  const Outcome mf1 = run({"report", scene.string(), "--format", "sky", "--sky", "reinhart:1"});
  EXPECT_EQ(tregenza.out, mf1.out);
  EXPECT_NE(tregenza.out, one.out);
}

TEST_F(SkyCli, BadSkiesAreRefusedSayingWhy) {
  const fs::path scene = write("street.json", kStreet);
  for (const std::string bad :
       {"reinhart:0", "reinhart:65", "reinhart:", "reinhart:2x", "klucher"}) {
    const Outcome refused = run({"report", scene.string(), "--format", "sky", "--sky", bad});
    EXPECT_EQ(refused.code, 2) << bad;
    EXPECT_NE(refused.err.find("--sky: '" + bad +
                               "' names no sky: tregenza or reinhart:N, N from 1 to 64"),
              std::string::npos)
        << refused.err;
  }
  const Outcome elsewhere = run({"report", scene.string(), "--sky", "tregenza"});
  EXPECT_EQ(elsewhere.code, 2);
  EXPECT_NE(elsewhere.err.find("--sky: applies only to --format sky"), std::string::npos)
      << elsewhere.err;
  const Outcome sampled = run({"report", scene.string(), "--format", "sky", "--method", "rays"});
  EXPECT_EQ(sampled.code, 2);
  EXPECT_NE(sampled.err.find("--format sky takes the exact lit areas of every sky patch; "
                             "--method rays does not apply"),
            std::string::npos)
      << sampled.err;
}

}  // namespace
}  // namespace shadowgen::test
