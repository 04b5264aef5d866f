// End-to-end tests of the `shadowgen` command: the built executable is run on scenes
// written to a temporary folder, and its exit code, output and files are checked.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int code = -1;
  std::string out;
  std::string err;
};

// A square ground (10 × 10 at z = 0) and a smaller square (4 × 4 at z = 1) above it, lit
// straight down: the ground's lit area is exactly 100 - 16.
constexpr const char* kTinyScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]], "holes": []},
    {"id": "occluder", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]], "holes": []}
  ],
  "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
})";

constexpr const char* kTinyCsv =
    "face_id,light_id,area,lit_area,lit_fraction\n"
    "ground,sun,100,84,0.83999999999999997\n"
    "occluder,sun,16,16,1\n";

std::string quoted(const std::string& arg) {
  std::string q = "'";
  for (const char c : arg) {
    if (c == '\'') {
      q += "'\\''";
    } else {
      q += c;
    }
  }
  return q + "'";
}

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           (std::string("shadowgen-cli-") + info->name() + "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "run");
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  // Runs shadowgen with `args`; its stdout and stderr are kept apart from the files the
  // tests look at, in dir_/run.
  Outcome run(const std::vector<std::string>& args) const {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `" " + std::string`.
    std::string command = quoted(SHADOWGEN_EXECUTABLE);
    for (const std::string& arg : args) {
      command += ' ';
      command += quoted(arg);
    }
    command += " >";
    command += quoted((dir_ / "run" / "out").string());
    command += " 2>";
    command += quoted((dir_ / "run" / "err").string());
    command += " </dev/null";
    const int status = std::system(command.c_str());
    Outcome result;
    result.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = contents(dir_ / "run" / "out");
    result.err = contents(dir_ / "run" / "err");
    return result;
  }

  // The files in the test's folder (not the run/ folder): what the command left behind.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      if (entry.path().filename() != "run") names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

TEST_F(Cli, GenerateThenReport) {
  const fs::path scene = write("scene.json", kTinyScene);
  const fs::path db = dir_ / "db.json";
  const Outcome generated = run({"generate", scene.string(), "-o", db.string()});
  ASSERT_EQ(generated.code, 0) << generated.err;
  EXPECT_EQ(generated.out, "");
  EXPECT_EQ(generated.err, "");
  EXPECT_EQ(files(), (std::vector<std::string>{"db.json", "scene.json"}));
  EXPECT_EQ(nlohmann::json::parse(contents(db))["format"], "shadowgen-shadowed/1");

  const Outcome from_db = run({"report", db.string()});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.out, kTinyCsv);
  EXPECT_EQ(from_db.err, "");
}

TEST_F(Cli, ReportFromSceneAndFromDatabaseAreByteIdentical) {
  const fs::path scene = write("scene.json", kTinyScene);
  const fs::path db = dir_ / "db.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string(), "--threads", "2"}).code, 0);

  const Outcome from_scene = run({"report", scene.string()});
  const Outcome from_db = run({"report", db.string(), "--format", "csv"});
  ASSERT_EQ(from_scene.code, 0) << from_scene.err;
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_scene.out, from_db.out);
  EXPECT_EQ(from_scene.out, kTinyCsv);

  const Outcome json_scene = run({"report", scene.string(), "--format", "json"});
  const Outcome json_db = run({"report", db.string(), "--format", "json"});
  ASSERT_EQ(json_scene.code, 0) << json_scene.err;
  EXPECT_EQ(json_scene.out, json_db.out);
}

TEST_F(Cli, ReportToAFile) {
  const fs::path scene = write("scene.json", kTinyScene);
  const Outcome csv = run({"report", scene.string(), "-o", (dir_ / "report.csv").string()});
  ASSERT_EQ(csv.code, 0) << csv.err;
  EXPECT_EQ(csv.out, "");
  EXPECT_EQ(contents(dir_ / "report.csv"), kTinyCsv);

  const Outcome json =
      run({"report", scene.string(), "--format", "json", "-o", (dir_ / "report.json").string()});
  ASSERT_EQ(json.code, 0) << json.err;
  const nlohmann::json report = nlohmann::json::parse(contents(dir_ / "report.json"));
  ASSERT_EQ(report["rows"].size(), 2u);
  EXPECT_EQ(report["rows"][0]["lit_area"], 84.0);
  EXPECT_EQ(report["lights"][0]["light_id"], "sun");
  EXPECT_EQ(report["lights"][0]["area"], 116.0);
  EXPECT_EQ(report["lights"][0]["lit_area"], 100.0);
  EXPECT_EQ(report["totals"]["lit_fraction"], 100.0 / 116.0);
  EXPECT_EQ(files(), (std::vector<std::string>{"report.csv", "report.json", "scene.json"}));
}

TEST_F(Cli, BrokenSceneExitsOneWithAMessageAndNoOutput) {
  const fs::path scene = write("broken.json", R"({
    "format": "shadowgen-scene/1",
    "polygons": [{"id": "stub", "outer": [[0,0,0],[1,0,0]], "holes": []}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })");
  const Outcome generated = run({"generate", scene.string(), "-o", (dir_ / "db.json").string()});
  EXPECT_EQ(generated.code, 1);
  EXPECT_EQ(generated.err.rfind("shadowgen: ", 0), 0u) << generated.err;
  EXPECT_NE(generated.err.find("broken.json"), std::string::npos) << generated.err;
  EXPECT_NE(generated.err.find("stub"), std::string::npos) << generated.err;
  EXPECT_EQ(std::count(generated.err.begin(), generated.err.end(), '\n'), 1) << generated.err;
  EXPECT_EQ(generated.out, "");

  const Outcome report = run({"report", scene.string(), "-o", (dir_ / "report.csv").string()});
  EXPECT_EQ(report.code, 1);
  EXPECT_EQ(report.err.rfind("shadowgen: ", 0), 0u) << report.err;
  EXPECT_EQ(files(), std::vector<std::string>{"broken.json"});
}

TEST_F(Cli, AFailedRunLeavesAnExistingOutputAlone) {
  const fs::path scene = write("broken.json", R"({"format": "shadowgen-scene/1", "polygons": [)");
  const fs::path db = write("db.json", "old contents");
  EXPECT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 1);
  EXPECT_EQ(contents(db), "old contents");
  EXPECT_EQ(files(), (std::vector<std::string>{"broken.json", "db.json"}));
}

TEST_F(Cli, UnreadableInputsExitOne) {
  const Outcome missing = run({"report", (dir_ / "missing.json").string()});
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("missing.json"), std::string::npos) << missing.err;

  const fs::path other = write("other.json", R"({"format": "something-else/3"})");
  const Outcome unknown = run({"report", other.string()});
  EXPECT_EQ(unknown.code, 1);
  EXPECT_NE(unknown.err.find("something-else/3"), std::string::npos) << unknown.err;

  const fs::path bad_db = write("bad-db.json", R"({"format": "shadowgen-shadowed/1"})");
  const Outcome bad = run({"report", bad_db.string()});
  EXPECT_EQ(bad.code, 1);
  EXPECT_EQ(bad.err.rfind("shadowgen: " + bad_db.string() + ": ", 0), 0u) << bad.err;

  const fs::path scene = write("scene.json", kTinyScene);
  const Outcome unwritable =
      run({"generate", scene.string(), "-o", (dir_ / "no" / "such" / "db.json").string()});
  EXPECT_EQ(unwritable.code, 1);
  EXPECT_NE(unwritable.err.find("db.json"), std::string::npos) << unwritable.err;
}

TEST_F(Cli, WarningsGoToStderrUnlessQuietAndAreErrorsWhenStrict) {
  const fs::path scene = write("bent.json", R"({
    "format": "shadowgen-scene/1",
    "polygons": [{"id": "bent", "outer": [[0,0,0],[1,0,0],[1,1,0.5],[0,1,0]], "holes": []}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })");
  const Outcome loud = run({"generate", scene.string(), "-o", (dir_ / "a.json").string()});
  EXPECT_EQ(loud.code, 0) << loud.err;
  EXPECT_NE(loud.err.find("warning"), std::string::npos) << loud.err;
  EXPECT_NE(loud.err.find("bent"), std::string::npos) << loud.err;

  const Outcome quiet =
      run({"generate", scene.string(), "-o", (dir_ / "b.json").string(), "--quiet"});
  EXPECT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(contents(dir_ / "a.json"), contents(dir_ / "b.json"));

  const Outcome strict =
      run({"generate", scene.string(), "-o", (dir_ / "c.json").string(), "--strict"});
  EXPECT_EQ(strict.code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "c.json"));

  const Outcome report_strict = run({"report", scene.string(), "--strict"});
  EXPECT_EQ(report_strict.code, 1);
  EXPECT_EQ(report_strict.out, "");
}

TEST_F(Cli, UsageErrorsExitTwo) {
  const fs::path scene = write("scene.json", kTinyScene);
  EXPECT_EQ(run({}).code, 2);
  EXPECT_EQ(run({"frobnicate"}).code, 2);
  EXPECT_EQ(run({"generate", scene.string()}).code, 2);                     // no -o
  EXPECT_EQ(run({"generate", "-o", (dir_ / "db.json").string()}).code, 2);  // no scene
  EXPECT_EQ(run({"report", scene.string(), "--format", "xml"}).code, 2);
  EXPECT_EQ(run({"report", scene.string(), "--bogus"}).code, 2);
  EXPECT_EQ(
      run({"generate", scene.string(), "-o", (dir_ / "db.json").string(), "--threads", "many"})
          .code,
      2);
  const Outcome usage = run({"report"});
  EXPECT_EQ(usage.code, 2);
  EXPECT_NE(usage.err.find("input"), std::string::npos) << usage.err;
  EXPECT_EQ(files(), std::vector<std::string>{"scene.json"});
}

TEST_F(Cli, HelpForEachSubcommand) {
  const Outcome top = run({"--help"});
  EXPECT_EQ(top.code, 0);
  EXPECT_NE(top.out.find("generate"), std::string::npos) << top.out;
  EXPECT_NE(top.out.find("report"), std::string::npos) << top.out;

  const Outcome generate = run({"generate", "--help"});
  EXPECT_EQ(generate.code, 0);
  for (const char* option : {"--output", "--strict", "--threads", "--quiet"}) {
    EXPECT_NE(generate.out.find(option), std::string::npos) << option << "\n" << generate.out;
  }
  const Outcome report = run({"report", "--help"});
  EXPECT_EQ(report.code, 0);
  for (const char* option : {"--format", "--output", "--strict"}) {
    EXPECT_NE(report.out.find(option), std::string::npos) << option << "\n" << report.out;
  }
}

}  // namespace
