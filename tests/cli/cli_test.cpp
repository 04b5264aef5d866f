// End-to-end tests of the `shadowgen` command: the built executable is run on scenes
// written to a temporary folder, and its exit code, output and files are checked.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"
#include "tests/cli/cli_scenes.h"

namespace shadowgen::test {
namespace {

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

// Two lights on a tilted plate and a post: a second scene that differs from the first.
constexpr const char* kPlateScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "plate", "outer": [[0,0,0],[8,0,0],[8,6,1],[0,6,1]], "holes": []},
    {"id": "post", "outer": [[3,2,2],[5,2,2],[5,3,2],[3,3,2]], "holes": []}
  ],
  "lights": [{"id": "noon", "type": "directional", "direction": [0.1,0.2,-1]},
             {"id": "bulb", "type": "point", "position": [4,3,6]}]
})";

constexpr const char* kTinyCsv =
    "face_id,light_id,area,lit_area,lit_fraction\n"
    "ground,sun,100,84,0.83999999999999997\n"
    "occluder,sun,16,16,1\n";

class Cli : public CliFolderTest<> {
 protected:
  Cli() : CliFolderTest("shadowgen-cli") {}
};

TEST_F(Cli, GenerateThenReport) {
  const fs::path scene = write("scene.json", kTinyScene);
  const fs::path db = dir_ / "db.json";
  const Outcome generated = run({"generate", scene.string(), "-o", db.string()});
  ASSERT_EQ(generated.code, 0) << generated.err;
  EXPECT_EQ(generated.out, "");
  EXPECT_EQ(generated.err, "");
  EXPECT_EQ(files(), (std::vector<std::string>{"db.json", "scene.json"}));
  EXPECT_EQ(nlohmann::json::parse(contents(db))["format"], "shadowgen-shadowed/2");

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
  const fs::path scene = write("broken.json", kStubScene);
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

// A run never replaces what it reads, however the output is spelled: the same path, a
// symbolic link to the input, or a hard link.
TEST_F(Cli, AnOutputThatIsAnInputIsRefused) {
  const fs::path scene = write("scene.json", kTinyScene);
  fs::create_symlink(scene, dir_ / "link.json");
  fs::create_hard_link(scene, dir_ / "hard.json");
  for (const char* output : {"scene.json", "link.json", "hard.json"}) {
    const std::string out = (dir_ / output).string();
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"generate", scene.string(), "-o", out},
          std::vector<std::string>{"report", scene.string(), "-o", out},
          std::vector<std::string>{"export", scene.string(), "--obj", out}}) {
      const Outcome r = run(args);
      EXPECT_EQ(r.code, 2) << args[0] << " -o " << output << ": " << r.err;
      EXPECT_NE(r.err.find("is the input"), std::string::npos) << r.err;
    }
  }
  EXPECT_EQ(contents(scene), kTinyScene);
  const fs::path db = dir_ / "db.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome render =
      run({"render", db.string(), "--eye", "0,0,10", "--target", "0,0,0", "--svg", db.string()});
  EXPECT_EQ(render.code, 2) << render.err;
  EXPECT_EQ(nlohmann::json::parse(contents(db))["format"], "shadowgen-shadowed/2");
}

// The mesh files a scene reads are inputs too: no run writes over one (they were once
// replaced by a database, an OBJ or a report, with exit 0).
TEST_F(Cli, AnOutputThatIsAMeshFileOfTheSceneIsRefused) {
  const std::string mesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  write("tri.obj", mesh);
  const fs::path scene = write("scene.json", R"({"format": "shadowgen-scene/1",
    "meshes": [{"id": "m", "file": "tri.obj"}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0, 0, -1]}]})");
  const std::string out = (dir_ / "tri.obj").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"generate", scene.string(), "-o", out},
        std::vector<std::string>{"report", scene.string(), "-o", out},
        std::vector<std::string>{"export", scene.string(), "--obj", out}}) {
    const Outcome r = run(args);
    EXPECT_EQ(r.code, 2) << args[0] << ": " << r.err;
    EXPECT_NE(r.err.find(out + ": is the input"), std::string::npos) << r.err;
  }
  EXPECT_EQ(contents(dir_ / "tri.obj"), mesh);
  EXPECT_EQ(files(), (std::vector<std::string>{"scene.json", "tri.obj"}));
}

// Out of memory: one line naming the input and exit 1, never an abort (a destructor
// that allocates once made it exit 134 with "std::bad_alloc" and no file named). The
// address space is limited to 160 MiB, which reading this scene's 100,000 faces outgrows.
TEST_F(Cli, RunningOutOfMemoryNamesTheInputAndExitsOne) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves far more address space than the limit";
#else
  std::string polygons;
  for (int i = 0; i < 100000; ++i) {
    if (i > 0) polygons += ",";
    const std::string x = std::to_string(i);
    polygons +=
        R"({"id": "p)" + x + R"(", "outer": [[)" + x + ",0,0],[" + x + ".5,0,0],[" + x + ",1,0]]}";
  }
  const fs::path scene = write("big.json", R"({"format": "shadowgen-scene/1", "polygons": [)" +
                                               polygons + R"(], "lights": []})");
  const fs::path db = dir_ / "db.json";
  const int code = shell("ulimit -v 163840 && " + quoted(SHADOWGEN_EXECUTABLE) + " generate " +
                         quoted(scene.string()) + " -o " + quoted(db.string()) + " 2> " +
                         quoted((dir_ / "run" / "err").string()));
  const std::string err = contents(dir_ / "run" / "err");
  EXPECT_EQ(code, 1) << err;
  EXPECT_EQ(err, "shadowgen: " + scene.string() +
                     ": out of memory: this input needs more memory than the process may use\n");
  EXPECT_FALSE(fs::exists(db));
#endif
}

// "-" is standard output for a report; an OBJ export is two files and cannot be one stream.
TEST_F(Cli, DashIsStandardOutput) {
  const fs::path scene = write("scene.json", kTinyScene);
  const Outcome report = run({"report", scene.string(), "-o", "-"});
  ASSERT_EQ(report.code, 0) << report.err;
  EXPECT_EQ(report.out, kTinyCsv);
  EXPECT_EQ(run({"export", scene.string(), "--obj", "-"}).code, 2);
  EXPECT_EQ(files(), (std::vector<std::string>{"scene.json"}));
}

// "-" as the input is standard input: a scene (its meshes relative to the working folder)
// or a database, named "-" in messages.
TEST_F(Cli, DashIsStandardInput) {
  const fs::path scene = write("scene.json", kTinyScene);
  const Outcome report = run_shadowgen({"report", "-"}, dir_ / "run", scene);
  ASSERT_EQ(report.code, 0) << report.err;
  EXPECT_EQ(report.out, kTinyCsv);

  const fs::path db = dir_ / "db.json";
  ASSERT_EQ(run_shadowgen({"generate", "-", "-o", db.string()}, dir_ / "run", scene).code, 0);
  const Outcome from_db = run_shadowgen({"report", "-"}, dir_ / "run", db);
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.out, kTinyCsv);

  const fs::path broken = write("broken.json", R"({"format": "shadowgen-scene/1", "polygons": [)");
  const Outcome bad = run_shadowgen({"report", "-"}, dir_ / "run", broken);
  EXPECT_EQ(bad.code, 1);
  EXPECT_EQ(bad.err.rfind("shadowgen: -: line 1, column 46: invalid JSON", 0), 0u) << bad.err;
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

// A file that starts with a NUL byte (a binary file) is not JSON that ends at once: every
// subcommand reading a scene or a database says where the NUL byte is.
TEST_F(Cli, AFileStartingWithANulByteIsSaidToHoldOneInEverySubcommand) {
  const fs::path binary = write("binary.json", std::string("\0\x01\x02{}", 5));
  const std::string message =
      "shadowgen: " + binary.string() +
      ": line 1, column 1: invalid JSON: a NUL byte (JSON text has none; is this a binary "
      "file?)\n";
  const std::string out = (dir_ / "out").string();
  const std::vector<std::vector<std::string>> commands = {
      {"generate", binary.string(), "-o", out + ".json"},
      {"report", binary.string()},
      {"export", binary.string(), "--obj", out + ".obj"},
      {"render", binary.string(), "--eye", "0,0,1", "--target", "0,0,0", "--svg", out + ".svg"},
      {"sun", binary.string()},
      {"merge", binary.string(), "-o", out + ".json"},
      {"compare", binary.string()}};
  for (const std::vector<std::string>& args : commands) {
    const Outcome outcome = run(args);
    EXPECT_EQ(outcome.code, 1) << args[0] << ": " << outcome.err;
    EXPECT_EQ(outcome.err, message) << args[0];
  }
  EXPECT_EQ(files(), std::vector<std::string>{"binary.json"});
}

// A device as the input is refused before a byte of it is read (/dev/zero would give NUL
// bytes without end).
TEST_F(Cli, ADeviceAsTheInputIsNotARegularFile) {
  for (const char* command : {"report", "generate"}) {
    std::vector<std::string> args{command, "/dev/zero"};
    if (std::string(command) == "generate")
      args.insert(args.end(), {"-o", (dir_ / "out.json").string()});
    const Outcome outcome = run(args);
    EXPECT_EQ(outcome.code, 1) << outcome.err;
    EXPECT_EQ(outcome.err, "shadowgen: /dev/zero: is not a regular file (a character device)\n");
  }
}

// A pipe (a FIFO, as a shell's <(...) gives one) gives its bytes once: a scene or a
// database through one is read whole, once, not scanned for its format and then found
// empty.
TEST_F(Cli, APipeAsTheInputIsReadOnce) {
  const fs::path scene = write("scene.json", kTinyScene);
  const fs::path db = dir_ / "db.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(shell("mkfifo " + quoted(fifo.string())), 0);
  for (const fs::path& input : {scene, db}) {
    ASSERT_EQ(
        shell("(timeout 60 cat " + quoted(input.string()) + " > " + quoted(fifo.string()) + " &)"),
        0);
    const Outcome report = run({"report", fifo.string()});
    EXPECT_EQ(report.code, 0) << report.err;
    EXPECT_EQ(report.out, kTinyCsv) << input;
  }
}

TEST_F(Cli, WarningsGoToStderrUnlessQuietAndAreErrorsWhenStrict) {
  const fs::path scene = write("bent.json", kBentScene);
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

// A word where the subcommand goes is named, with the subcommands there are (CLI11 said
// "A subcommand is required" of `shadowgen frobnicate`); every parse error begins with
// "shadowgen: " as the other errors do, then the hint.
TEST_F(Cli, AnUnknownSubcommandIsNamedWithTheSubcommandsThereAre) {
  const std::string names = "generate, report, export, render, sun, merge, compare, view";
  const std::string hint = "\nRun with --help for more information.\n";
  const Outcome unknown = run({"frobnicate", "x.json"});
  EXPECT_EQ(unknown.code, 2);
  EXPECT_EQ(unknown.out, "");
  EXPECT_EQ(unknown.err, "shadowgen: frobnicate: not a subcommand of shadowgen (its subcommands: " +
                             names + ")" + hint);
  const Outcome none = run({});
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.err, "shadowgen: a subcommand is required: " + names + hint);
  const Outcome option = run({"--bogus"});
  EXPECT_EQ(option.code, 2);
  EXPECT_EQ(
      option.err,
      "shadowgen: --bogus: not an option of shadowgen; a subcommand comes first: " + names + hint);
  const Outcome extra = run({"report", "a.json", "--bogus"});
  EXPECT_EQ(extra.code, 2);
  EXPECT_EQ(extra.err, "shadowgen: The following argument was not expected: --bogus" + hint);
  const Outcome missing = run({"generate", "a.json"});
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(missing.err, "shadowgen: --output is required" + hint);
  const Outcome format = run({"report", "a.json", "--format", "xml"});
  EXPECT_EQ(format.code, 2);
  EXPECT_EQ(format.err.rfind("shadowgen: --format: xml not in {", 0), 0u) << format.err;
  EXPECT_EQ(files(), std::vector<std::string>{});
}

// Every numeric option refuses NaN, an infinity out of its range and a number out of its
// range while the arguments are parsed: exit 2 before any work, whatever the input (here
// one that does not exist, which would be exit 1 had anything been read), with its bounds
// written readably (cli/number_options.h). `--threshold nan` and `--scale nan` once did the
// work and then failed with exit 1; ranges once printed the largest double as 309 digits.
TEST_F(Cli, NumericOptionsRefuseNanAndInfinityAtParseTime) {
  const std::string missing = (dir_ / "missing.json").string();
  const std::string svg = (dir_ / "out.svg").string();
  struct Case {
    std::vector<std::string> args;
    std::string message;  // the first line on stderr
  };
  const std::vector<Case> cases = {
      {{"report", missing, "--format", "sun-hours", "--threshold", "nan"},
       "--threshold: nan is not a number"},
      {{"report", missing, "--format", "sun-hours", "--threshold", "2,inf"},
       "--threshold: inf must be finite"},
      {{"report", missing, "--format", "sun-hours", "--threshold", "-1"},
       "--threshold: -1 must be at least 0"},
      {{"report", missing, "--format", "table", "--top", "-1"},
       "--top: -1 must lie between 0 and 1000000000"},
      {{"report", missing, "--method", "rays", "--samples", "nan"},
       "--samples: expected a whole number, got nan"},
      {{"render", missing, "--eye", "1,2,3", "--target", "0,0,0", "--ortho", "--scale", "nan",
        "--svg", svg},
       "--scale: nan is not a number"},
      {{"render", missing, "--eye", "1,2,3", "--target", "0,0,0", "--fov", "inf", "--svg", svg},
       "--fov: inf must be at least 1e-06 and below 180 degrees"},
      {{"render", missing, "--eye", "1,2,3", "--target", "0,0,0", "--width", "0", "--svg", svg},
       "--width: 0 must lie between 1 and 1000000"},
      {{"render", missing, "--eye", "nan,2,3", "--target", "0,0,0", "--svg", svg},
       "--eye: expected X,Y,Z (three numbers), got nan,2,3"},
      {{"render", missing, "--sun-hours", "day", "--bands", "nan", "--svg", svg},
       "--bands: nan is not a number"},
      {{"render", missing, "--sun-hours", "day", "--bands", "1e999", "--svg", svg},
       "--bands: expected a number, got 1e999"},
  };
  for (const Case& c : cases) {
    const Outcome outcome = run(c.args);
    EXPECT_EQ(outcome.code, 2) << c.message << "\n" << outcome.err;
    EXPECT_EQ(outcome.err.rfind("shadowgen: " + c.message + "\n", 0), 0u) << outcome.err;
    EXPECT_EQ(outcome.err.find("179769313486231570000"), std::string::npos) << outcome.err;
  }
  EXPECT_EQ(files(), std::vector<std::string>{});
}

TEST_F(Cli, HelpForEachSubcommand) {
  const Outcome top = run({"--help"});
  EXPECT_EQ(top.code, 0);
  EXPECT_NE(top.out.find("generate"), std::string::npos) << top.out;
  EXPECT_NE(top.out.find("report"), std::string::npos) << top.out;

  const Outcome generate = run({"generate", "--help"});
  EXPECT_EQ(generate.code, 0);
  for (const char* option : {"--output", "--strict", "--threads", "--quiet", "Several scenes",
                             "a folder", "NAME.shadowed.json", "progress"}) {
    EXPECT_NE(generate.out.find(option), std::string::npos) << option << "\n" << generate.out;
  }
  const Outcome report = run({"report", "--help"});
  EXPECT_EQ(report.code, 0);
  for (const char* option : {"--format", "--output", "--strict", "table", "--top"}) {
    EXPECT_NE(report.out.find(option), std::string::npos) << option << "\n" << report.out;
  }
}

// The help of a subcommand that computes no shadow speaks of what it does with the lights
// it is not given (render's --lights once said a scene's other lights are not generated).
TEST_F(Cli, HelpOfSubcommandsThatGenerateNothingSpeaksOfNoGenerating) {
  const Outcome render = run({"render", "--help"});
  EXPECT_EQ(render.code, 0);
  EXPECT_EQ(render.out.find("generated"), std::string::npos) << render.out;
  EXPECT_NE(render.out.find("the database's other lights are not drawn"), std::string::npos)
      << render.out;
  // The subcommands that show progress say that --quiet silences it.
  for (const char* command : {"report", "compare", "export", "render", "merge"}) {
    const Outcome help = run({command, "--help"});
    EXPECT_NE(help.out.find("do not print reading warnings or the progress line"),
              std::string::npos)
        << command << "\n"
        << help.out;
  }
  const Outcome sun = run({"sun", "--help"});
  EXPECT_EQ(sun.code, 0);
  EXPECT_EQ(sun.out.find("generated"), std::string::npos) << sun.out;
  EXPECT_NE(sun.out.find("the other lights' instants are not listed"), std::string::npos)
      << sun.out;
}

TEST_F(Cli, SeveralScenesGiveTheDatabasesOfEachAlone) {
  const fs::path tiny = write("tiny.json", kTinyScene);
  const fs::path plate = write("plate.json", kPlateScene);
  ASSERT_EQ(run({"generate", tiny.string(), "-o", (dir_ / "tiny-alone.json").string()}).code, 0);
  ASSERT_EQ(run({"generate", plate.string(), "-o", (dir_ / "plate-alone.json").string()}).code, 0);

  const fs::path out = dir_ / "out" / "databases";  // made, parents included
  const Outcome both =
      run({"generate", tiny.string(), plate.string(), "-o", out.string(), "--threads", "2"});
  ASSERT_EQ(both.code, 0) << both.err;
  EXPECT_EQ(both.out, "");
  EXPECT_EQ(both.err, "");  // stderr is a file here: no progress line
  EXPECT_EQ(files(out), (std::vector<std::string>{"plate.shadowed.json", "tiny.shadowed.json"}));
  EXPECT_EQ(contents(out / "tiny.shadowed.json"), contents(dir_ / "tiny-alone.json"));
  EXPECT_EQ(contents(out / "plate.shadowed.json"), contents(dir_ / "plate-alone.json"));
  EXPECT_NE(contents(out / "tiny.shadowed.json"), contents(out / "plate.shadowed.json"));

  // An existing folder is fine, and the databases in it are replaced whole.
  const Outcome again = run({"generate", plate.string(), tiny.string(), "-o", out.string()});
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(contents(out / "tiny.shadowed.json"), contents(dir_ / "tiny-alone.json"));
  EXPECT_EQ(files(out), (std::vector<std::string>{"plate.shadowed.json", "tiny.shadowed.json"}));
}

TEST_F(Cli, ABadSceneStopsTheRunAndLeavesTheDatabasesBeforeIt) {
  const fs::path good = write("good.json", kTinyScene);
  const fs::path bad = write("bad.json", kStubScene);
  const fs::path later = write("later.json", kPlateScene);
  const fs::path out = dir_ / "out";
  const Outcome run_out =
      run({"generate", good.string(), bad.string(), later.string(), "-o", out.string()});
  EXPECT_EQ(run_out.code, 1);
  EXPECT_EQ(run_out.err.rfind("shadowgen: " + bad.string() + ": ", 0), 0u) << run_out.err;
  EXPECT_NE(run_out.err.find("stub"), std::string::npos) << run_out.err;
  EXPECT_EQ(std::count(run_out.err.begin(), run_out.err.end(), '\n'), 1) << run_out.err;
  // The first scene's database is whole; nothing for the bad scene (no temporary file
  // either) nor for the one after it.
  EXPECT_EQ(files(out), std::vector<std::string>{"good.shadowed.json"});
  ASSERT_EQ(run({"generate", good.string(), "-o", (dir_ / "alone.json").string()}).code, 0);
  EXPECT_EQ(contents(out / "good.shadowed.json"), contents(dir_ / "alone.json"));

  // A bad first scene: nothing is written, not even the folder.
  const Outcome first =
      run({"generate", bad.string(), good.string(), "-o", (dir_ / "other").string()});
  EXPECT_EQ(first.code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "other"));
}

TEST_F(Cli, SeveralScenesNeedDistinctNamesAndAFolder) {
  const fs::path a = write("a.json", kTinyScene);
  fs::create_directories(dir_ / "sub");
  const fs::path other_a = write("sub/a.json", kPlateScene);
  const fs::path b = write("b.json", kPlateScene);

  const Outcome clash =
      run({"generate", a.string(), other_a.string(), "-o", (dir_ / "out").string()});
  EXPECT_EQ(clash.code, 2);
  EXPECT_NE(clash.err.find("a.shadowed.json"), std::string::npos) << clash.err;
  const Outcome twice = run({"generate", a.string(), a.string(), "-o", (dir_ / "out").string()});
  EXPECT_EQ(twice.code, 2);

  const fs::path file = write("file.json", "not a folder");
  const Outcome not_folder = run({"generate", a.string(), b.string(), "-o", file.string()});
  EXPECT_EQ(not_folder.code, 2);
  EXPECT_NE(not_folder.err.find("folder"), std::string::npos) << not_folder.err;
  EXPECT_EQ(contents(file), "not a folder");

  // A database named like an input scene would replace it.
  const fs::path shadowed_name = write("a.shadowed.json", kPlateScene);
  const Outcome replace =
      run({"generate", a.string(), shadowed_name.string(), "-o", dir_.string()});
  EXPECT_EQ(replace.code, 2);
  EXPECT_EQ(contents(shadowed_name), kPlateScene);

  EXPECT_FALSE(fs::exists(dir_ / "out"));
  EXPECT_EQ(files(),
            (std::vector<std::string>{"a.json", "a.shadowed.json", "b.json", "file.json", "sub"}));
}

TEST_F(Cli, ProgressOnATerminalOnlyAndNotWhenQuiet) {
  const fs::path scene = write("scene.json", kPlateScene);
  // Not a terminal (stderr is a file): nothing, with or without --quiet.
  const Outcome piped = run({"generate", scene.string(), "-o", (dir_ / "a.json").string()});
  ASSERT_EQ(piped.code, 0) << piped.err;
  EXPECT_EQ(piped.err, "");
  const Outcome quiet_piped =
      run({"generate", scene.string(), "-o", (dir_ / "b.json").string(), "--quiet"});
  ASSERT_EQ(quiet_piped.code, 0) << quiet_piped.err;
  EXPECT_EQ(quiet_piped.err, "");

  // A terminal: one line redrawn in place, ending with both lights done.
  const Outcome shown =
      run_shadowgen_on_terminal({"generate", scene.string(), "-o", (dir_ / "c.json").string()});
  ASSERT_EQ(shown.code, 0) << shown.out;
  std::string line_start = scene.string();  // "\r<scene>: lights ", built up piece by
  line_start.insert(0, 1, '\r');            // piece for GCC 12's false -Wrestrict
  line_start += ": lights ";
  EXPECT_EQ(shown.out.rfind(line_start + "0/2, ", 0), 0u) << shown.out;
  EXPECT_NE(shown.out.find(line_start + "2/2, last light "), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find(" faces, "), std::string::npos) << shown.out;
  EXPECT_EQ(std::count(shown.out.begin(), shown.out.end(), '\n'), 1) << shown.out;
  EXPECT_EQ(contents(dir_ / "c.json"), contents(dir_ / "a.json"));

  // --quiet on a terminal: nothing.
  const Outcome quiet = run_shadowgen_on_terminal(
      {"generate", scene.string(), "-o", (dir_ / "d.json").string(), "--quiet"});
  ASSERT_EQ(quiet.code, 0) << quiet.out;
  EXPECT_EQ(quiet.out, "");
  EXPECT_EQ(contents(dir_ / "d.json"), contents(dir_ / "a.json"));
}

TEST_F(Cli, ReportAsATable) {
  const fs::path scene = write("scene.json", kPlateScene);
  const Outcome table = run({"report", scene.string(), "--format", "table"});
  ASSERT_EQ(table.code, 0) << table.err;
  EXPECT_EQ(table.err, "");
  const std::string header = table.out.substr(0, table.out.find('\n'));
  EXPECT_EQ(header.rfind("light_id  faces  lit_faces  ", 0), 0u) << table.out;
  EXPECT_NE(header.find("  area  lit_area  lit_fraction"), std::string::npos) << table.out;
  for (const char* id : {"noon", "bulb", "plate", "post"}) {
    EXPECT_NE(table.out.find(id), std::string::npos) << id << "\n" << table.out;
  }
  EXPECT_NE(table.out.find("most shadowed faces under noon (lowest lit fraction first, 2 of 2)"),
            std::string::npos)
      << table.out;

  // From the database the same; --top 1 lists one face per light; to a file as the others.
  const fs::path db = dir_ / "db.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  EXPECT_EQ(run({"report", db.string(), "--format", "table"}).out, table.out);
  const Outcome top = run({"report", db.string(), "--format", "table", "--top", "1", "-o",
                           (dir_ / "table.txt").string()});
  ASSERT_EQ(top.code, 0) << top.err;
  EXPECT_EQ(top.out, "");
  EXPECT_NE(contents(dir_ / "table.txt").find("(lowest lit fraction first, 1 of 2)"),
            std::string::npos);

  // csv stays the default, and --top belongs to the table.
  EXPECT_EQ(
      run({"report", db.string()}).out.rfind("face_id,light_id,area,lit_area,lit_fraction\n", 0),
      0u);
  const Outcome misplaced = run({"report", db.string(), "--top", "3"});
  EXPECT_EQ(misplaced.code, 2);
  EXPECT_NE(misplaced.err.find("--top"), std::string::npos) << misplaced.err;
  EXPECT_EQ(run({"report", db.string(), "--format", "table", "--top", "-1"}).code, 2);
}

}  // namespace
}  // namespace shadowgen::test
