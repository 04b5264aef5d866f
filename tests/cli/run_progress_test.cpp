// The progress line of every long-running subcommand (cli/run_progress.h): its stages,
// drawn to a string stream, and end to end on a pseudo-terminal (report and compare on a
// scene, export, render, merge), silent where stderr is not a terminal.

#include "cli/run_progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::cli {
namespace {

TEST(FormatProgress, AStageIsShownInPlaceOfTheLights) {
  ProgressLine line;
  line.scene = "db.json";
  line.stage = "splitting faces by light sets";
  line.lights_total = 3;
  line.seconds = 2.36;
  EXPECT_EQ(format_progress(line), "db.json: splitting faces by light sets, 2.4 s");
}

TEST(RunProgress, GeneratesThenGoesThroughItsStagesOnOneLine) {
  std::ostringstream out;
  RunProgress progress("scene.json", &out);
  LoadOptions options;
  std::vector<std::string> warnings;
  options.on_warning = [&](const std::string& warning) {
    out << "warning: " << warning << '\n';
    warnings.push_back(warning);
  };
  progress.watch(options);
  ASSERT_TRUE(options.on_scene);
  ASSERT_TRUE(options.generate.on_light_done);
  options.on_warning("bent face");  // while reading: no line yet, nothing to end
  Scene scene;
  scene.lights.resize(2);
  options.on_scene(scene);
  options.generate.on_light_done(0, LightStats{});
  options.generate.on_light_done(1, LightStats{});
  progress.stage("splitting faces by light sets");
  options.on_warning("late");  // ends the line, which the next stage draws anew
  progress.stage("writing out.obj");
  progress.finish();
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("warning: bent face\n\rscene.json: lights 0/2, ", 0), 0u) << text;
  const std::size_t done = text.find("\rscene.json: lights 2/2, last light 0 faces, ");
  const std::size_t split = text.find("\rscene.json: splitting faces by light sets, ");
  const std::size_t late = text.find("\nwarning: late\n\rscene.json: writing out.obj, ");
  EXPECT_NE(done, std::string::npos) << text;
  EXPECT_LT(done, split) << text;
  EXPECT_LT(split, late) << text;
  EXPECT_NE(late, std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << text;
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(warnings, (std::vector<std::string>{"bent face", "late"}));
}

TEST(RunProgress, SilentWithoutAStream) {
  RunProgress progress("scene.json", nullptr);
  LoadOptions options;
  progress.watch(options);
  EXPECT_FALSE(options.on_scene);
  EXPECT_FALSE(options.generate.on_light_done);
  EXPECT_FALSE(progress.lights(3));
  EXPECT_NO_THROW(progress.stage("writing"));
  EXPECT_NO_THROW(progress.finish());
}

}  // namespace
}  // namespace shadowgen::cli

namespace shadowgen::test {
namespace {

constexpr const char* kYard = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "yard", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "post", "outer": [[4,4,0],[5,4,0],[5,4,2],[4,4,2]]}
  ],
  "site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "utc_offset_h": 0},
  "lights": [{"id": "noon", "type": "sun", "from": "2026-03-21T11:00",
              "to": "2026-03-21T13:00", "step_min": 60},
             {"id": "lamp", "type": "point", "position": [5, 8, 3]}],
  "views": [{"id": "main", "eye": [20,-15,12], "target": [5,5,0]}]
})";

class ProgressCli : public CliFolderTest<> {
 protected:
  ProgressCli() : CliFolderTest("shadowgen-progress") {}

  void SetUp() override {
    CliFolderTest::SetUp();
    scene_ = write("yard.json", kYard).string();
    db_ = (dir_ / "yard.shadowed.json").string();
    const Outcome generated = run({"generate", scene_, "-o", db_, "--keep-instants"});
    ASSERT_EQ(generated.code, 0) << generated.err;
  }

  // The run on a terminal shows each of `lines` (the start of a drawing of the line, "\r"
  // first), in order, then ends its line; the same run off a terminal shows nothing.
  void ExpectProgress(const std::vector<std::string>& args, const std::vector<std::string>& lines) {
    const Outcome shown = run_shadowgen_on_terminal(args);
    ASSERT_EQ(shown.code, 0) << shown.out;
    std::size_t at = 0;
    for (const std::string& line : lines) {
      const std::size_t found = shown.out.find('\r' + line, at);
      EXPECT_NE(found, std::string::npos) << line << "\n" << shown.out;
      if (found != std::string::npos) at = found;
    }
    EXPECT_NE(shown.out.find("\r\n", at), std::string::npos) << shown.out;  // the line ended
    const Outcome quiet = run_shadowgen_on_terminal([&] {
      std::vector<std::string> more = args;
      more.push_back("--quiet");
      return more;
    }());
    ASSERT_EQ(quiet.code, 0) << quiet.out;
    EXPECT_EQ(quiet.out.find(" s\r"), std::string::npos) << quiet.out;
    const Outcome plain = run(args);
    ASSERT_EQ(plain.code, 0) << plain.err;
    EXPECT_EQ(plain.err, "");
  }

  std::string scene_, db_;
};

TEST_F(ProgressCli, ReportOnASceneShowsItsGeneration) {
  ExpectProgress({"report", scene_, "-o", (dir_ / "r.csv").string()},
                 {scene_ + ": lights 0/4, ", scene_ + ": lights 4/4, last light "});
}

TEST_F(ProgressCli, CompareOnASceneShowsItsExactGenerationThenEachTrial) {
  ExpectProgress({"compare", scene_, "--methods", "rays:4,shadow-map:64:samples=4", "-o",
                  (dir_ / "c.txt").string()},
                 {scene_ + ": lights 0/4, ", scene_ + ": lights 4/4, last light ",
                  scene_ + ": trial 2/3, rays 4, ", scene_ + ": trial 3/3, shadow-map 4 @ 64, "});
}

TEST_F(ProgressCli, ExportShowsItsStages) {
  const std::string obj = (dir_ / "yard.obj").string();
  ExpectProgress({"export", db_, "-o", obj},
                 {db_ + ": splitting faces by light sets, ", db_ + ": writing " + obj + ", "});
  // On a scene, its generation first.
  ExpectProgress({"export", scene_, "-o", obj},
                 {scene_ + ": lights 0/4, ", scene_ + ": splitting faces by light sets, "});
}

TEST_F(ProgressCli, RenderShowsItsStages) {
  const std::string svg = (dir_ / "yard.svg").string(), png = (dir_ / "yard.png").string();
  ExpectProgress(
      {"render", db_, "--view", "main", "--width", "40", "--height", "30", "-o", svg, "-o", png},
      {db_ + ": drawing " + svg + ", ", db_ + ": drawing " + png + ", ", db_ + ": writing, "});
}

TEST_F(ProgressCli, MergeShowsTheShardsRead) {
  std::vector<std::string> shards;
  for (const char* k : {"1", "2"}) {
    shards.push_back((dir_ / (std::string("shard-") + k + ".json")).string());
    const Outcome made =
        run({"generate", scene_, "-o", shards.back(), "--instants", std::string(k) + "/2"});
    ASSERT_EQ(made.code, 0) << made.err;
  }
  const std::string merged = (dir_ / "merged.json").string();
  ExpectProgress({"merge", shards[0], shards[1], "-o", merged},
                 {merged + ": reading shard 1/2 (" + shards[0] + "), ",
                  merged + ": reading shard 2/2 (" + shards[1] + "), ",
                  merged + ": joining 2 shards, ", merged + ": writing, "});
}

}  // namespace
}  // namespace shadowgen::test
