// End-to-end tests of `shadowgen render --png`: the courtyard example's database drawn
// pixel by pixel by each view method, read back with libpng; the PNG written atomically
// (a failed run leaves the old file and no temporary file); usage errors.

#include <gtest/gtest.h>
#include <png.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

class PngRenderCli : public CliFolderTest<> {
 protected:
  PngRenderCli() : CliFolderTest("shadowgen-png") {}

  void SetUp() override {
    CliFolderTest::SetUp();
    const fs::path scene = dir_ / "courtyard.json";
    fs::copy_file(fs::path(SHADOWGEN_EXAMPLES_DIR) / "scenes" / "courtyard.json", scene);
    db_ = dir_ / "courtyard.shadowed.json";
    const Outcome generated = run({"generate", scene.string(), "-o", db_.string(), "--quiet"});
    ASSERT_EQ(generated.code, 0) << generated.err;
    fs::remove(scene);
  }

  Outcome render(const std::vector<std::string>& more) {
    std::vector<std::string> args{"render",  db_.string(), "--view",   "main",
                                  "--width", "96",         "--height", "72"};
    args.insert(args.end(), more.begin(), more.end());
    return run(args);
  }

  fs::path db_;
};

TEST_F(PngRenderCli, EachMethodWritesAValidPng) {
  std::vector<Png> pictures;
  for (const std::string method : {"exact", "shadow-map", "volumes", "stencil", "angular"}) {
    const fs::path png = dir_ / (method + ".png");
    const Outcome out = render({"--png", png.string(), "--shadows", method});
    ASSERT_EQ(out.code, 0) << method << ": " << out.err;
    EXPECT_EQ(out.out, "");
    const Png read = read_png(png);
    ASSERT_TRUE(read.ok) << method;
    EXPECT_EQ(read.width, 96);
    EXPECT_EQ(read.height, 72);
    pictures.push_back(read);
  }
  // Exact is the default; volumes and stencil agree with it on most pixels.
  const fs::path plain = dir_ / "plain.png";
  ASSERT_EQ(render({"--png", plain.string()}).code, 0);
  EXPECT_EQ(contents(plain), contents(dir_ / "exact.png"));
  for (const std::size_t other : {std::size_t{2}, std::size_t{3}, std::size_t{4}}) {
    std::size_t differ = 0;
    for (std::size_t i = 0; i < pictures[0].rgb.size(); ++i) {
      differ += pictures[0].rgb[i] != pictures[other].rgb[i];
    }
    EXPECT_LE(differ, pictures[0].rgb.size() / 50) << other;
  }

  // --svg and --png together: both written.
  const Outcome both =
      render({"--svg", (dir_ / "both.svg").string(), "--png", (dir_ / "both.png").string(),
              "--shadows", "shadow-map", "--resolution", "256"});
  ASSERT_EQ(both.code, 0) << both.err;
  EXPECT_TRUE(fs::exists(dir_ / "both.svg"));
  EXPECT_TRUE(read_png(dir_ / "both.png").ok);
  // --resolution sets the angular span table's rows, and they show.
  const fs::path coarse = dir_ / "coarse.png";
  const Outcome rows =
      render({"--png", coarse.string(), "--shadows", "angular", "--resolution", "8"});
  ASSERT_EQ(rows.code, 0) << rows.err;
  EXPECT_NE(contents(coarse), contents(dir_ / "angular.png"));
  EXPECT_EQ(sorted_names(dir_, dir_ / "run"),
            (std::vector<std::string>{"angular.png", "both.png", "both.svg", "coarse.png",
                                      "courtyard.shadowed.json", "exact.png", "plain.png",
                                      "shadow-map.png", "stencil.png", "volumes.png"}));
}

// The RGB bytes in which two pictures of one size differ.
std::size_t differing(const Png& a, const Png& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) n += a.rgb[i] != b.rgb[i];
  return n;
}

TEST_F(PngRenderCli, StencilSilhouettesLoseTheOpenCourtyardsShadows) {
  // The courtyard's wall and canopy are single polygons: no edge of theirs is shared, so
  // Heidmann's silhouette volumes have no side, and the picture (z-pass: the eye is in no
  // shadow) has none of their shadows, which the per-polygon stencil keeps.
  std::vector<Png> pictures;
  for (const std::string method : {"exact", "stencil", "stencil-silhouettes"}) {
    const fs::path png = dir_ / (method + ".png");
    const Outcome out = render({"--png", png.string(), "--shadows", method});
    ASSERT_EQ(out.code, 0) << method << ": " << out.err;
    pictures.push_back(read_png(png));
    ASSERT_TRUE(pictures.back().ok) << method;
    EXPECT_EQ(pictures.back().width, 96);
    EXPECT_EQ(pictures.back().height, 72);
  }
  // Off by a few boundary pixels from exact per polygon; the missing shadows only brighten.
  EXPECT_LE(differing(pictures[0], pictures[1]), pictures[0].rgb.size() / 50);
  EXPECT_GT(differing(pictures[0], pictures[2]), 4 * differing(pictures[0], pictures[1]));
  std::size_t darker = 0, brighter = 0;
  for (std::size_t i = 0; i + 2 < pictures[1].rgb.size(); i += 3) {
    int d = 0;
    for (std::size_t k = 0; k < 3; ++k) d += pictures[2].rgb[i + k] - pictures[1].rgb[i + k];
    darker += d < 0;
    brighter += d > 0;
  }
  EXPECT_EQ(darker, 0u);
  EXPECT_GT(brighter, 150u);  // of 96 × 72
}

TEST_F(PngRenderCli, AFailedRunLeavesTheOldFile) {
  const fs::path png = dir_ / "out.png";
  write_file(png, "old");
  // eye == target: bad input, exit 1, nothing written.
  const Outcome bad = run({"render", db_.string(), "--eye", "1,1,1", "--target", "1,1,1", "--png",
                           png.string(), "--shadows", "volumes"});
  EXPECT_EQ(bad.code, 1) << bad.err;
  EXPECT_EQ(contents(png), "old");
  EXPECT_EQ(sorted_names(dir_, dir_ / "run"),
            (std::vector<std::string>{"courtyard.shadowed.json", "out.png"}));
  // A good run replaces it whole.
  ASSERT_EQ(render({"--png", png.string()}).code, 0);
  EXPECT_TRUE(read_png(png).ok);
  EXPECT_EQ(sorted_names(dir_, dir_ / "run"),
            (std::vector<std::string>{"courtyard.shadowed.json", "out.png"}));
}

TEST_F(PngRenderCli, UsageErrors) {
  const std::string png = (dir_ / "u.png").string();
  const std::string svg = (dir_ / "u.svg").string();
  auto expect_usage = [&](const std::vector<std::string>& more, const std::string& says) {
    const Outcome out = render(more);
    EXPECT_EQ(out.code, 2) << out.err;
    EXPECT_NE(out.err.find(says), std::string::npos) << out.err;
  };
  expect_usage({"--svg", svg, "--shadows", "volumes"}, "--png");
  expect_usage({"--png", png, "--shadows", "stencils"}, "stencils");
  expect_usage({"--png", png, "--shadows", "rays"}, "rays");
  expect_usage({"--png", png, "--resolution", "64"}, "--resolution applies only");
  expect_usage({"--png", png, "--shadows", "volumes", "--resolution", "64"},
               "--resolution applies only");
  expect_usage({"--png", png, "--shadows", "stencil-silhouettes", "--resolution", "64"},
               "--resolution applies only");
  expect_usage({}, "-o FILE.svg or -o FILE.png is required");
  expect_usage({"--png", db_.string()}, "is the input");
  expect_usage({"--png", png, "--svg", png}, "name the same file");
  EXPECT_FALSE(fs::exists(png));
  EXPECT_FALSE(fs::exists(svg));
}

// libpng writes pictures up to 1,000,000 pixels a side (PNG_USER_WIDTH_MAX and
// PNG_USER_HEIGHT_MAX): a larger one is refused at the option, before any work, not by
// libpng once drawn.
TEST_F(PngRenderCli, ASideBeyondWhatLibpngWritesIsAUsageError) {
  const std::string png = (dir_ / "wide.png").string();
  for (const char* side : {"--width", "--height"}) {
    const Outcome out =
        run({"render", db_.string(), "--view", "main", side, "1000001", "--png", png});
    EXPECT_EQ(out.code, 2) << out.err;
    EXPECT_EQ(out.err.substr(0, out.err.find('\n')),
              "shadowgen: " + std::string(side) + ": 1000001 must lie between 1 and 1000000");
  }
  EXPECT_FALSE(fs::exists(png));
}

// A picture too large for the memory the process may use is said of the PNG file and its
// size, and nothing is written.
TEST_F(PngRenderCli, APictureTooLargeForTheMemoryNamesThePngFile) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves far more address space than the limit";
#else
  const fs::path png = dir_ / "huge.png";
  const fs::path err = dir_ / "run" / "err";
  // 1 GiB of address space: Embree's device needs some 200 MiB of it to start.
  const int code =
      shell("ulimit -v 1048576 && " + quoted(SHADOWGEN_EXECUTABLE) + " render " +
            quoted(db_.string()) + " --view main --width 1000000 --height 1000000 --png " +
            quoted(png.string()) + " 2> " + quoted(err.string()));
  EXPECT_EQ(code, 1) << contents(err);
  EXPECT_EQ(contents(err), "shadowgen: " + png.string() +
                               ": out of memory: a picture of 1000000 × 1000000 pixels needs more "
                               "memory than the process may use\n");
  EXPECT_FALSE(fs::exists(png));
#endif
}

}  // namespace
}  // namespace shadowgen::test
