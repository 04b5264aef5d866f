// Regression cases of the clipper, one file per case in tests/clipper/regressions/, named
// after what broke: comment lines (#) say what, then the subject and the clip as WKT on
// one line each. Each is checked like the oracle suites: both argument orders against
// CGAL's exact answer, every piece valid, areas within 1e-12 of the operand's
// area or within the clipper's stated error bound (area_error_bound), whichever is larger.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/clipper/snap_shortcut_check.h"
#include "tests/support/clip_check.h"
#include "tests/support/expect.h"
#include "tests/support/wkt.h"

namespace shadowgen::test {
namespace {

namespace fs = std::filesystem;

const fs::path kRegressionDir = SHADOWGEN_REGRESSION_DIR;

std::vector<std::string> regression_files() {
  std::vector<std::string> names;
  if (!fs::is_directory(kRegressionDir)) return names;
  for (const fs::directory_entry& entry : fs::directory_iterator(kRegressionDir)) {
    if (entry.path().extension() == ".wkt") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class ClipRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(ClipRegression, MatchesExactOverlay) {
  std::ifstream in(kRegressionDir / (GetParam() + ".wkt"));
  ASSERT_TRUE(in) << "cannot read " << kRegressionDir / (GetParam() + ".wkt");
  std::vector<std::string> geometries;
  for (std::string line; std::getline(in, line);) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    geometries.push_back(line);
  }
  ASSERT_EQ(geometries.size(), 2u) << "expected a subject line and a clip line";
  const PolygonSet2 subject = read_wkt(geometries[0]).polygons;
  const PolygonSet2 clip = read_wkt(geometries[1]).polygons;
  ASSERT_EQ(input_problem(subject), "") << "the subject is outside clip()'s contract";
  ASSERT_EQ(input_problem(clip), "") << "the clip is outside clip()'s contract";
  // Snap rounding's shortcut, where it decides, gives what its rounds give.
  EXPECT_EQ(shortcut_disagreement(subject, clip), "");
  EXPECT_EQ(shortcut_disagreement(clip, subject), "");
  const ClipCheck check =
      check_clip(subject, clip, {.swapped = true, .symmetric_difference = true});
  const double bound = area_error_bound(subject, clip);
  const std::string why = check.failure(std::max(1e-12 * check.exact.subject, bound),
                                        std::max(1e-12 * check.exact.clip, bound));
  if (!why.empty()) {
    ADD_FAILURE() << GetParam() << ": " << why << '\n'
                  << describe(check, subject, clip)
                  << "picture: " << write_case_svg(GetParam(), subject, clip, &check.forward);
  }
}

std::string TestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Files, ClipRegression, ::testing::ValuesIn(regression_files()), TestName);

TEST(ClipRegression, CorpusIsPresent) {
  EXPECT_FALSE(regression_files().empty()) << "no .wkt files in " << kRegressionDir;
}

}  // namespace
}  // namespace shadowgen::test
