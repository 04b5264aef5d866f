// Databases written as gzip (a path ending in ".gz") end to end: `zcat` gives the plain
// database byte for byte, every command reads one as it reads the plain file (by its
// magic bytes, so a renamed one too, and from standard input), shards and merges take and
// make them, and a truncated or corrupt one is one line naming it and what is wrong.

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

const fs::path kScenes = fs::path(SHADOWGEN_EXAMPLES_DIR) / "scenes";

class GzipDatabaseCli : public CliFolderTest<> {
 protected:
  GzipDatabaseCli() : CliFolderTest("shadowgen-gzip-db") {}

  // The garden example generated to dir_/name.
  fs::path generated(const std::string& name, const std::string& threads = "2") const {
    const fs::path out = dir_ / name;
    const Outcome o = run(
        {"generate", (kScenes / "garden.json").string(), "-o", out.string(), "--threads", threads});
    EXPECT_EQ(o.code, 0) << o.err;
    if (out.extension() == ".gz") {
      EXPECT_EQ(contents(out).substr(0, 2), "\x1f\x8b") << name;
    }
    return out;
  }
};

TEST_F(GzipDatabaseCli, ZcatGivesThePlainDatabase) {
  const fs::path plain = generated("garden.json"), gzip = generated("garden.json.gz");
  EXPECT_LT(contents(gzip).size(), contents(plain).size() / 3);
  EXPECT_EQ(contents(generated("garden-1.json.gz", "1")), contents(gzip));  // any threads
  if (shell("command -v zcat >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "zcat is not installed (Debian's gzip package): the decompressed bytes are "
                    "not compared";
  }
  ASSERT_EQ(shell("zcat " + quoted(gzip.string()) + " > " + quoted((dir_ / "unzipped").string())),
            0);
  EXPECT_EQ(shell("cmp -s " + quoted((dir_ / "unzipped").string()) + " " + quoted(plain.string())),
            0);
}

TEST_F(GzipDatabaseCli, EveryOutputIsTheSameFromTheGzipDatabase) {
  const fs::path plain = generated("garden.json"), gzip = generated("garden.json.gz");
  const fs::path renamed = dir_ / "renamed.json";  // gzip inside, named as plain text
  fs::copy_file(gzip, renamed);
  const fs::path svg = dir_ / "out.svg", obj = dir_ / "out.obj", glb = dir_ / "out.glb";
  const std::vector<std::pair<std::vector<std::string>, fs::path>> outputs = {
      {{"report", "DB"}, {}},
      {{"report", "DB", "--format", "json"}, {}},
      {{"report", "DB", "--format", "sun-hours"}, {}},
      {{"render", "DB", "--view", "main", "-o", svg.string()}, svg},
      {{"render", "DB", "--view", "main", "--sun-hours", "march21", "-o", svg.string()}, svg},
      {{"export", "DB", "-o", obj.string()}, obj},
      {{"export", "DB", "-o", glb.string(), "--sun-hours", "march21"}, glb},
  };
  for (const auto& [command, file] : outputs) {
    const std::string from_plain = output(command, plain, file);
    EXPECT_FALSE(from_plain.empty()) << command[0] << " " << command.back();
    EXPECT_EQ(output(command, gzip, file), from_plain) << command[0] << " " << command.back();
    EXPECT_EQ(output(command, renamed, file), from_plain) << command[0] << " " << command.back();
  }
  // The viewer's model, which is titled by the file's name: both copies named alike (the
  // page's assets are stand-ins, only the model is compared).
  fs::create_directories(dir_ / "assets");
  write("assets/index.html", "<html></html>\n");
  write("assets/viewer.js", "\n");
  for (const auto& [database, folder] : {std::pair{plain, "plain"}, std::pair{gzip, "gzip"}}) {
    fs::create_directories(dir_ / folder);
    fs::copy_file(database, dir_ / folder / "garden.json");
    ASSERT_EQ(shell("cd " + quoted((dir_ / folder).string()) +
                    " && SHADOWGEN_VIEWER_ASSETS=../assets " + quoted(SHADOWGEN_EXECUTABLE) +
                    " view garden.json -o viewer >../run/out 2>../run/err"),
              0)
        << contents(dir_ / "run" / "err");
  }
  const std::string model = contents(dir_ / "plain" / "viewer" / "model.js");
  EXPECT_FALSE(model.empty());
  EXPECT_TRUE(contents(dir_ / "gzip" / "viewer" / "model.js") == model);
  // From standard input too.
  const Outcome piped = run_shadowgen({"report", "-", "--format", "sun-hours"}, dir_ / "run", gzip);
  EXPECT_EQ(piped.code, 0) << piped.err;
  EXPECT_EQ(piped.out, output({"report", "DB", "--format", "sun-hours"}, plain));
}

// generate takes scenes only: a gzip scene is read as the plain one, and a gzip database
// is refused as the plain one is, for what it is.
TEST_F(GzipDatabaseCli, GenerateTellsGzipScenesAndDatabasesByContent) {
  const fs::path plain = generated("garden.json"), gzip = generated("garden.json.gz");
  const Outcome db = run({"generate", gzip.string(), "-o", (dir_ / "again.json").string()});
  EXPECT_EQ(db.code, 1);
  EXPECT_EQ(db.err, "shadowgen: " + gzip.string() +
                        ": format: unsupported format 'shadowgen-shadowed/2'; this reader reads "
                        "'shadowgen-scene/1'\n");
  // The scene compressed by gzip(1), under a plain name.
  ASSERT_EQ(shell("gzip -c " + quoted((kScenes / "garden.json").string()) + " > " +
                  quoted((dir_ / "scene.json").string())),
            0);
  ASSERT_EQ(contents(dir_ / "scene.json").substr(0, 2), "\x1f\x8b");
  const fs::path from_gzip = dir_ / "from-gzip.json";
  const Outcome o = run({"generate", (dir_ / "scene.json").string(), "-o", from_gzip.string()});
  ASSERT_EQ(o.code, 0) << o.err;
  // The same database but for the scene's file name, which the database records.
  std::string expected = contents(plain);
  const std::string name = "\"" + (kScenes / "garden.json").string() + "\"";
  for (std::size_t at; (at = expected.find(name)) != std::string::npos;) {
    expected.replace(at, name.size(), "\"" + (dir_ / "scene.json").string() + "\"");
  }
  EXPECT_TRUE(contents(from_gzip) == expected);
}

TEST_F(GzipDatabaseCli, ShardsAndMergeTakeAndMakeGzip) {
  const fs::path scene = kScenes / "garden.json";
  const fs::path whole = generated("whole.json.gz");
  std::vector<std::string> merge = {"merge"};
  for (const std::string k : {"1", "2"}) {
    const fs::path shard = dir_ / ("shard-" + k + (k == "1" ? ".json.gz" : ".json"));
    ASSERT_EQ(run({"generate", scene.string(), "-o", shard.string(), "--instants", k + "/2"}).code,
              0);
    if (k == "1") {
      EXPECT_EQ(contents(shard).substr(0, 2), "\x1f\x8b");
    }
    merge.push_back(shard.string());
  }
  merge.insert(merge.end(), {"-o", (dir_ / "merged.json.gz").string()});
  const Outcome o = run(merge);
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(contents(dir_ / "merged.json.gz"), contents(whole));
}

TEST_F(GzipDatabaseCli, TruncatedOrCorruptGzipIsOneLineNamingTheFile) {
  const std::string gzip = contents(generated("garden.json.gz"));
  const fs::path truncated = write("truncated.json.gz", gzip.substr(0, gzip.size() - 4));
  std::string flipped = gzip;
  flipped[flipped.size() - 8] ^= 1;  // the CRC-32 of the last member
  const fs::path corrupt = write("corrupt.json.gz", flipped);
  const std::vector<std::pair<fs::path, std::string>> cases = {
      {truncated, "the gzip data ends before its last member does (a truncated file)"},
      {corrupt, "corrupt gzip data in the member at byte 0: incorrect data check"},
  };
  for (const auto& [file, problem] : cases) {
    for (const std::string command : {"report", "export", "render"}) {
      std::vector<std::string> args = {command, file.string(), "-o"};
      args.push_back((dir_ / (command == "report"   ? "out.csv"
                              : command == "export" ? "out.obj"
                                                    : "out.svg"))
                         .string());
      if (command == "render") args.insert(args.end(), {"--view", "main"});
      const Outcome o = run(args);
      EXPECT_EQ(o.code, 1) << command;
      EXPECT_EQ(o.err, "shadowgen: " + file.string() + ": " + problem + "\n") << command;
    }
  }
  EXPECT_EQ(files(),
            std::vector<std::string>({"corrupt.json.gz", "garden.json.gz", "truncated.json.gz"}));
}

}  // namespace
}  // namespace shadowgen::test
