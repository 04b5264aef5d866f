// The files a run reads and writes (cli/run_files.h), end to end: no output replaces a
// file the run reads, two outputs never name one file, and outputs that are not plain
// files (/dev/stdout, a file beyond the size limit) are written as a shell user expects.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"
#include "tests/shadowgen/weather/epw_text.h"

namespace shadowgen::test {
namespace {

// A unit square lit from above, at a site its weather file gives.
constexpr const char* kWeatherScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [{"id": "tile", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
  "weather": "site.epw",
  "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}],
  "views": [{"id": "top", "eye": [0.5,0.5,5], "target": [0.5,0.5,0], "up": [0,1,0]}]
})";

class RunFilesCli : public CliFolderTest<> {
 protected:
  RunFilesCli() : CliFolderTest("shadowgen-run-files") {}

  // The usage error's whole stderr.
  static std::string usage_error(const std::string& message) {
    return "shadowgen: " + message + "\nRun with --help for more information.\n";
  }
};

// The scene's weather file is read as its mesh files are: no output may replace it (it
// once did, with exit 0, for every subcommand that reads a scene).
TEST_F(RunFilesCli, TheScenesWeatherFileIsAnInputNoOutputReplaces) {
  const std::string weather = joined(epw_lines());
  write("site.epw", weather);
  const std::string scene = write("scene.json", kWeatherScene).string();
  const std::string epw = (dir_ / "site.epw").string();
  const std::vector<std::vector<std::string>> runs = {
      {"report", scene, "-o", epw},     {"report", scene, "--format", "json", "-o", epw},
      {"sun", scene, "-o", epw},        {"generate", scene, "-o", epw},
      {"export", scene, "--obj", epw},  {"compare", scene, "--methods", "rays:4", "-o", epw},
      {"compare", scene, "--plot", epw}};
  for (const std::vector<std::string>& args : runs) {
    const Outcome r = run(args);
    const std::string option = args[args.size() - 2];
    EXPECT_EQ(r.code, 2) << args[0] << " " << option;
    EXPECT_EQ(r.err,
              usage_error(option + " " + epw + ": is the input " + epw + "; it would be replaced"));
  }
  fs::create_symlink("site.epw", dir_ / "link.epw");
  const std::string link = (dir_ / "link.epw").string();
  const Outcome through_link = run({"report", scene, "-o", link});
  EXPECT_EQ(through_link.code, 2);
  EXPECT_EQ(through_link.err,
            usage_error("-o " + link + ": is the input " + epw + "; it would be replaced"));
  EXPECT_EQ(contents(dir_ / "site.epw"), weather);
  EXPECT_EQ(files(), (std::vector<std::string>{"link.epw", "scene.json", "site.epw"}));
}

// compare -o X --plot X once exited 0 with the plot lost under the table: two outputs of
// one run naming one file, by path, link or hard link, is a usage error before any work.
TEST_F(RunFilesCli, TwoOutputsNamingOneFileAreAUsageError) {
  const std::string scene = write("scene.json", kWeatherScene).string();
  write("site.epw", joined(epw_lines()));
  const std::string out = (dir_ / "out.txt").string();
  const std::string old_file = write("old.txt", "old\n").string();
  fs::create_hard_link(old_file, dir_ / "hard.txt");
  fs::create_symlink("old.txt", dir_ / "soft.txt");
  const std::string hard = (dir_ / "hard.txt").string();
  const std::string soft = (dir_ / "soft.txt").string();
  const struct {
    std::vector<std::string> args;
    std::string message;
  } cases[] = {
      {{"compare", scene, "-o", out, "--plot", out},
       "-o " + out + " and --plot " + out + " name the same file; one would be lost"},
      {{"compare", scene, "-o", old_file, "--plot", hard},
       "-o " + old_file + " and --plot " + hard + " name the same file; one would be lost"},
      {{"compare", scene, "--plot", soft, "-o", old_file},
       "-o " + old_file + " and --plot " + soft + " name the same file; one would be lost"},
      {{"compare", scene, "-o", "-", "--plot", "/dev/stdout"},
       "-o - and --plot /dev/stdout name the same file; one would be lost"},
      {{"export", scene, "--obj", soft},
       "--obj " + soft + " and --obj's MTL " + (dir_ / "soft.mtl").string() +
           " name the same file; one would be lost"},
  };
  fs::create_symlink("soft.txt", dir_ / "soft.mtl");  // the MTL of soft.txt is old.txt too
  for (const auto& c : cases) {
    const Outcome r = run(c.args);
    EXPECT_EQ(r.code, 2) << c.message;
    EXPECT_EQ(r.err, usage_error(c.message));
    EXPECT_EQ(r.out, "");
  }
  EXPECT_EQ(contents(old_file), "old\n");
  EXPECT_EQ(files(), (std::vector<std::string>{"hard.txt", "old.txt", "scene.json", "site.epw",
                                               "soft.mtl", "soft.txt"}));

  const std::string db = (dir_ / "db.json").string();
  ASSERT_EQ(run({"generate", scene, "-o", db}).code, 0);
  const Outcome render = run({"render", db, "--view", "top", "--svg", old_file, "--png", hard});
  EXPECT_EQ(render.code, 2);
  EXPECT_EQ(render.err, usage_error("--svg " + old_file + " and --png " + hard +
                                    " name the same file; one would be lost"));
  EXPECT_EQ(contents(old_file), "old\n");
}

// /dev/stdout is the file behind descriptor 1: written where the shell has got to, so that
// what it wrote around the run stays (the file was once renamed over, and "before" lost).
TEST_F(RunFilesCli, StandardOutputAsAFileKeepsWhatTheShellWroteAroundTheRun) {
  const std::string scene = write("scene.json", kWeatherScene).string();
  write("site.epw", joined(epw_lines()));
  const Outcome plain = run({"report", scene});
  ASSERT_EQ(plain.code, 0) << plain.err;
  const fs::path out = dir_ / "out.txt";
  const std::string shadowgen = quoted(SHADOWGEN_EXECUTABLE);
  ASSERT_EQ(shell("{ echo before; " + shadowgen + " report " + quoted(scene) +
                  " -o /dev/stdout; echo after; } > " + quoted(out.string())),
            0);
  EXPECT_EQ(contents(out), "before\n" + plain.out + "after\n");
  const fs::path piped = dir_ / "piped.txt";
  ASSERT_EQ(shell(shadowgen + " report " + quoted(scene) + " -o /dev/stdout | cat > " +
                  quoted(piped.string())),
            0);
  EXPECT_EQ(contents(piped), plain.out);
  EXPECT_EQ(files(), (std::vector<std::string>{"out.txt", "piped.txt", "scene.json", "site.epw"}));
}

// Under `ulimit -f` a run once died of SIGXFSZ without a word, leaving its hidden temporary
// file: now the write fails, naming the file, with exit 1 and nothing left behind.
TEST_F(RunFilesCli, TheFileSizeLimitIsAWriteErrorNamingTheFile) {
  const std::string scene = write("scene.json", kWeatherScene).string();
  write("site.epw", joined(epw_lines()));
  const std::string db = (dir_ / "db.json").string();
  const fs::path err = dir_ / "run" / "err";
  const int code = shell("ulimit -f 1; " + quoted(SHADOWGEN_EXECUTABLE) + " generate " +
                         quoted(scene) + " -o " + quoted(db) + " 2> " + quoted(err.string()));
  EXPECT_EQ(code, 1);
  EXPECT_EQ(contents(err), "shadowgen: cannot write '" + db + "': write failed: File too large\n");
  EXPECT_EQ(files(), (std::vector<std::string>{"scene.json", "site.epw"}));
}

}  // namespace
}  // namespace shadowgen::test
