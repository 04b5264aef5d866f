// Every text output named "*.gz" is written as gzip (shadowgen/output/atomic_file.h):
// `gzip -dc` of it gives the output under the plain name byte for byte, for each report
// format, the sun's instants, the comparison of methods, SVG pictures and OBJ and glTF
// models; a binary format (PNG, binary glTF) under such a name is a usage error before any
// work.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_harness.h"
#include "tests/cli/cli_scenes.h"

namespace shadowgen::test {
namespace {

class GzipOutputCli : public CliFolderTest<> {
 protected:
  GzipOutputCli() : CliFolderTest("shadowgen-gzip-output") {}

  void SetUp() override {
    CliFolderTest::SetUp();
    write("march.epw", march_epw("0.2"));
    scene_ = write("yard.json", kMarchYardScene);
    database_ = dir_ / "yard.shadowed.json";
    ASSERT_EQ(run({"generate", scene_.string(), "-o", database_.string()}).code, 0);
  }

  // What `command` writes to `name` (its placeholder "OUT"), and to `name` + ".gz" read
  // back through gzip -dc; the .gz file is checked to be gzip.
  std::pair<std::string, std::string> plain_and_unzipped(std::vector<std::string> command,
                                                         const std::string& name) const {
    std::pair<std::string, std::string> texts;
    for (const bool gzip : {false, true}) {
      const fs::path out = dir_ / (name + (gzip ? ".gz" : ""));
      std::vector<std::string> args = command;
      for (std::string& arg : args) {
        if (arg == "OUT") arg = out.string();
      }
      const Outcome o = run(args);
      EXPECT_EQ(o.code, 0) << o.err;
      if (!gzip) {
        texts.first = contents(out);
        continue;
      }
      EXPECT_EQ(contents(out).substr(0, 2), "\x1f\x8b") << name;
      const fs::path unzipped = dir_ / "unzipped";
      EXPECT_EQ(shell("gzip -dc " + quoted(out.string()) + " > " + quoted(unzipped.string())), 0)
          << name;
      texts.second = contents(unzipped);
    }
    return texts;
  }

  fs::path scene_, database_;
};

TEST_F(GzipOutputCli, GzipOfEveryTextOutputGivesThePlainOutput) {
  const std::string scene = scene_.string(), db = database_.string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> outputs = {
      {{"report", db, "-o", "OUT"}, "report.csv"},
      {{"report", db, "--format", "json", "-o", "OUT"}, "report.json"},
      {{"report", db, "--format", "sun-hours", "-o", "OUT"}, "sun-hours.csv"},
      {{"report", db, "--format", "energyplus", "-o", "OUT"}, "schedule.csv"},
      {{"report", db, "--format", "irradiation", "--weather", (dir_ / "march.epw").string(), "-o",
        "OUT"},
       "irradiation.csv"},
      {{"report", scene, "--format", "radiation", "--sky", "reinhart:1", "-o", "OUT"},
       "radiation.csv"},
      {{"report", scene, "--format", "sky", "--sky", "reinhart:1", "-o", "OUT"}, "sky.csv"},
      {{"report", scene, "--format", "energyplus-sky", "-o", "OUT"}, "energyplus-sky.csv"},
      {{"sun", scene, "-o", "OUT"}, "sun.csv"},
      {{"render", db, "--eye", "5,-20,12", "--target", "5,5,0", "-o", "OUT"}, "yard.svg"},
      {{"export", db, "-o", "OUT"}, "yard.obj"},
      {{"export", db, "-o", "OUT"}, "yard.gltf"},
  };
  for (const auto& [command, name] : outputs) {
    const auto [plain, unzipped] = plain_and_unzipped(command, name);
    EXPECT_FALSE(plain.empty()) << name;
    EXPECT_TRUE(unzipped == plain) << name;
  }
  // The OBJ under a .gz name keeps naming the plain MTL beside it, so that gzip -d gives
  // the pair.
  EXPECT_EQ(contents(dir_ / "yard.mtl").empty(), false);
  EXPECT_FALSE(fs::exists(dir_ / "yard.obj.mtl"));
}

// The comparison's CSV holds each method's time, which differs from run to run, and the
// mark that follows from it: its rows are compared without those two columns.
TEST_F(GzipOutputCli, GzipOfTheComparisonGivesItsCsv) {
  const auto [plain, unzipped] = plain_and_unzipped(
      {"compare", scene_.string(), "--methods", "rays:4", "--format", "csv", "-o", "OUT"},
      "compare.csv");
  const auto plain_rows = csv_rows(plain), unzipped_rows = csv_rows(unzipped);
  ASSERT_EQ(unzipped_rows.size(), plain_rows.size());
  ASSERT_GT(plain_rows.size(), 1u);
  const auto& header = plain_rows[0];
  for (std::size_t r = 0; r < plain_rows.size(); ++r) {
    ASSERT_EQ(unzipped_rows[r].size(), header.size());
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == "seconds" || header[c] == "pareto") continue;
      EXPECT_EQ(unzipped_rows[r][c], plain_rows[r][c]) << header[c];
    }
  }
}

TEST_F(GzipOutputCli, BinaryFormatsAreNotWrittenAsGzip) {
  const std::string db = database_.string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> refusals = {
      {{"render", db, "--eye", "5,-20,12", "--target", "5,5,0", "-o",
        (dir_ / "yard.png.gz").string()},
       "-o " + (dir_ / "yard.png.gz").string() +
           ": a PNG picture is compressed already; it is not written as gzip"},
      {{"render", db, "--eye", "5,-20,12", "--target", "5,5,0", "--png",
        (dir_ / "yard.png.gz").string()},
       "--png " + (dir_ / "yard.png.gz").string() +
           ": a PNG picture is compressed already; it is not written as gzip"},
      {{"export", db, "-o", (dir_ / "yard.glb.gz").string()},
       "-o " + (dir_ / "yard.glb.gz").string() +
           ": a binary glTF file is compressed already; it is not written as gzip"},
  };
  for (const auto& [command, message] : refusals) {
    const Outcome o = run(command);
    EXPECT_EQ(o.code, 2) << message;
    EXPECT_NE(o.err.find(message), std::string::npos) << o.err;
  }
  EXPECT_EQ(files(), std::vector<std::string>({"march.epw", "yard.json", "yard.shadowed.json"}));
}

}  // namespace
}  // namespace shadowgen::test
