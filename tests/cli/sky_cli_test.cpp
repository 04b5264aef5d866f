// `shadowgen report --format sky`: the sky view factor of every face, from the sky's
// patches as lights, end to end.

#include <gtest/gtest.h>

#include <algorithm>
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
  EXPECT_NE(elsewhere.err.find("--sky: applies only to --format sky, energyplus-sky and radiation"),
            std::string::npos)
      << elsewhere.err;
  const Outcome sampled = run({"report", scene.string(), "--format", "sky", "--method", "rays"});
  EXPECT_EQ(sampled.code, 2);
  EXPECT_NE(sampled.err.find("--format sky takes the exact lit areas of every sky patch; "
                             "--method rays does not apply"),
            std::string::npos)
      << sampled.err;
}

// EnergyPlus's diffuse sky shading ratios from its 144 directions: the open roof and wall
// get 1 exactly, the canyon's floor 7/16 and 2/24 (tests/shadowgen/sky/energyplus_sky_test.cpp
// computes them by hand); the same bytes on one thread and two, from a database too.
TEST_F(SkyCli, EnergyPlusSkyRatiosPerSurface) {
  const fs::path scene = write("street.json", kStreet);
  const Outcome one =
      run({"report", scene.string(), "--format", "energyplus-sky", "--threads", "1"});
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(one.err, "");
  const auto rows = csv_rows(one.out);
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"surface_name", "dif_shdg_ratio_iso_sky",
                                               "dif_shdg_ratio_horiz"}));
  EXPECT_EQ(rows[1], (std::vector<std::string>{"ROOF", "1", "1"}));
  EXPECT_EQ(rows[2], (std::vector<std::string>{"WALL", "1", "1"}));
  EXPECT_EQ(rows[3][0], "STREET");
  EXPECT_NEAR(std::stod(rows[3][1]), 7.0 / 16.0, 1e-14);
  EXPECT_NEAR(std::stod(rows[3][2]), 2.0 / 24.0, 1e-14);
  const fs::path db = dir_ / "street.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome two = run({"report", db.string(), "--format", "energyplus-sky", "--threads", "2"});
  ASSERT_EQ(two.code, 0) << two.err;
  EXPECT_EQ(one.out, two.out);

  // --sky adds the ratio over its patches, the same on any number of threads.
  const Outcome fine1 = run({"report", scene.string(), "--format", "energyplus-sky", "--sky",
                             "reinhart:2", "--threads", "1"});
  const Outcome fine2 = run({"report", scene.string(), "--format", "energyplus-sky", "--sky",
                             "reinhart:2", "--threads", "2"});
  ASSERT_EQ(fine1.code, 0) << fine1.err;
  EXPECT_EQ(fine1.out, fine2.out);
  const auto fine = csv_rows(fine1.out);
  ASSERT_EQ(fine.size(), 6u);
  EXPECT_EQ(fine[0].back(), "sky_shading_ratio");
  EXPECT_EQ(fine[1], (std::vector<std::string>{"ROOF", "1", "1", "1"}));
  EXPECT_EQ(std::vector<std::string>(fine[3].begin(), fine[3].end() - 1), rows[3]);
  EXPECT_NEAR(std::stod(fine[3][3]) / std::cos(std::atan(2.0)), 1.0, 0.02);
}

TEST_F(SkyCli, EnergyPlusSkyRefusesWhatEnergyPlusCannotName) {
  const fs::path scene = write("bad.json", R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "roof", "outer": [[0,0,3],[10,0,3],[10,10,3],[0,10,3]]},
    {"id": "Roof", "outer": [[20,0,3],[30,0,3],[30,10,3],[20,10,3]]}
  ]
})");
  const fs::path out = dir_ / "ratios.csv";
  const Outcome refused =
      run({"report", scene.string(), "--format", "energyplus-sky", "-o", out.string()});
  EXPECT_EQ(refused.code, 1);
  EXPECT_EQ(refused.err, "shadowgen: " + scene.string() +
                             ": face 'Roof': is the EnergyPlus surface name ROOF in upper case, "
                             "as face 'roof' is\n");
  EXPECT_FALSE(fs::exists(out));
  const Outcome sampled =
      run({"report", scene.string(), "--format", "energyplus-sky", "--method", "rays"});
  EXPECT_EQ(sampled.code, 2);
  EXPECT_NE(sampled.err.find("--format energyplus-sky takes the exact lit areas of every sky "
                             "patch; --method rays does not apply"),
            std::string::npos)
      << sampled.err;
  const Outcome safe = run({"report", scene.string(), "--format", "energyplus-sky", "--csv-safe"});
  EXPECT_EQ(safe.code, 2);
  EXPECT_NE(safe.err.find("--csv-safe: applies only to"), std::string::npos) << safe.err;
}

// compare --sky: the exact column is report --format sky's, each trial's errors are those of
// its column against the exact one, and the rays' error falls as their points grow.
TEST_F(SkyCli, CompareSkyGivesTheExactAndSampledViewFactors) {
  const fs::path scene = write("street.json", kStreet);
  const Outcome sky = run({"report", scene.string(), "--format", "sky", "--sky", "reinhart:1"});
  ASSERT_EQ(sky.code, 0) << sky.err;
  const Outcome compared = run({"compare", scene.string(), "--sky", "reinhart:1", "--methods",
                                "rays:4,rays:64,rays:1024", "--format", "csv", "--threads", "2"});
  ASSERT_EQ(compared.code, 0) << compared.err;
  const std::size_t blank = compared.out.find("\n\n");
  ASSERT_NE(blank, std::string::npos) << compared.out;
  const auto trials = csv_rows(compared.out.substr(0, blank + 1));
  const auto faces = csv_rows(compared.out.substr(blank + 2));
  ASSERT_EQ(trials.size(), 5u);
  EXPECT_EQ(trials[0], (std::vector<std::string>{"method", "samples", "resolution", "seconds",
                                                 "mean_error", "max_error", "mean_relative_error",
                                                 "max_relative_error", "worst_face", "pareto"}));
  ASSERT_EQ(faces.size(), 6u);
  EXPECT_EQ(faces[0], (std::vector<std::string>{"face_id", "area", "exact", "rays:4", "rays:64",
                                                "rays:1024"}));
  const auto sky_rows = csv_rows(sky.out);
  for (std::size_t f = 1; f < faces.size(); ++f) {
    EXPECT_EQ(faces[f][0], sky_rows[f][0]);
    EXPECT_EQ(faces[f][1], sky_rows[f][1]);
    EXPECT_EQ(faces[f][2], sky_rows[f][2]);  // byte for byte
  }
  std::vector<double> mean;
  for (std::size_t t = 1; t < trials.size(); ++t) {
    double largest = 0.0, sum = 0.0;
    for (std::size_t f = 1; f < faces.size(); ++f) {
      const double error = std::fabs(std::stod(faces[f][1 + t]) - std::stod(faces[f][2]));
      largest = std::max(largest, error);
      sum += error;
    }
    EXPECT_EQ(std::stod(trials[t][5]), largest) << trials[t][0] << trials[t][1];
    EXPECT_NEAR(std::stod(trials[t][4]), sum / 5.0, 1e-15) << trials[t][0] << trials[t][1];
    mean.push_back(std::stod(trials[t][4]));
  }
  EXPECT_EQ(trials[1][4], "0");  // the exact one
  EXPECT_GT(mean[1], mean[2]);
  EXPECT_GT(mean[2], mean[3]);

  const Outcome table =
      run({"compare", scene.string(), "--sky", "tregenza", "--methods", "rays:16"});
  ASSERT_EQ(table.code, 0) << table.err;
  EXPECT_EQ(table.out.rfind("sky view factors over 5 faces, tregenza (145 patches), against the "
                            "exact method\n",
                            0),
            0u)
      << table.out;
  const Outcome view = run({"compare", scene.string(), "--sky", "tregenza", "--view", "v"});
  EXPECT_EQ(view.code, 2);
  EXPECT_NE(view.err.find("--view excludes --sky"), std::string::npos) << view.err;
}

}  // namespace
}  // namespace shadowgen::test
