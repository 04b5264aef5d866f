// End-to-end tests of sun paths cut into shards: `generate --instants K/N` writes shard K
// of N, `merge` joins the N shards into the very file one `generate` writes; the other
// commands refuse a shard, and every way of getting the shards wrong exits with one
// message and leaves no file.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

// A yard north of a 4 m wall at Greenwich over 21 March 2026 every 10 minutes (72
// instants with the sun up: 5 blocks of 16), and a lamp that is no instant of it.
const std::string kYard = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "yard", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "wall", "outer": [[0,-0.5,0],[10,-0.5,0],[10,-0.5,4],[0,-0.5,4]]},
    {"id": "post", "outer": [[4,4,0],[5,4,0],[5,4,2],[4,4,2]]}
  ],
  "site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "utc_offset_h": 0},
  "lights": [{"id": "march21", "type": "sun", "from": "2026-03-21T00:00",
              "to": "2026-03-21T23:59", "step_min": 10},
             {"id": "lamp", "type": "point", "position": [5, 8, 3]}]
})";

class ShardCli : public CliFolderTest<> {
 protected:
  ShardCli() : CliFolderTest("shadowgen-shard") {}

  // Writes shard k of n of `scene` to dir_/shard-k.json; its path.
  fs::path shard(const fs::path& scene, int k, int n, const std::string& threads = "1") {
    const fs::path out = dir_ / ("shard-" + std::to_string(k) + ".json");
    const Outcome o = run({"generate", scene.string(), "-o", out.string(), "--instants",
                           std::to_string(k) + "/" + std::to_string(n), "--threads", threads});
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(o.err, "");
    return out;
  }
};

TEST_F(ShardCli, MergedShardsAreTheFileOneGenerateWrites) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path whole = dir_ / "whole.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", whole.string()}).code, 0);
  for (const int n : {2, 3, 6}) {  // 6 shards of 5 blocks: one holds no instant
    std::vector<std::string> args = {"merge"};
    for (int k = n; k >= 1; --k) {
      args.push_back(shard(scene, k, n, k % 2 == 0 ? "2" : "1").string());
    }
    const fs::path merged = dir_ / "merged.json";
    args.insert(args.end(), {"-o", merged.string()});
    const Outcome o = run(args);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(o.err, "");
    EXPECT_EQ(contents(merged), contents(whole)) << n << " shards";
    // And the report of the merged file is the report of the scene.
    EXPECT_EQ(run({"report", merged.string(), "--format", "sun-hours"}).out,
              run({"report", scene.string(), "--format", "sun-hours"}).out);
  }
}

TEST_F(ShardCli, ShardsOfLitAreasAloneMergeIntoTheFileOfOneRunToo) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path whole = dir_ / "whole.json", merged = dir_ / "merged.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", whole.string(), "--areas-only"}).code, 0);
  std::vector<std::string> args = {"merge"};
  for (int k = 1; k <= 3; ++k) {
    const fs::path out = dir_ / ("shard-" + std::to_string(k) + ".json");
    ASSERT_EQ(run({"generate", scene.string(), "-o", out.string(), "--instants",
                   std::to_string(k) + "/3", "--areas-only"})
                  .code,
              0);
    args.push_back(out.string());
  }
  args.insert(args.end(), {"-o", merged.string()});
  const Outcome o = run(args);
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(contents(merged), contents(whole));
  EXPECT_EQ(contents(whole).find("\"nodes\""), std::string::npos);
}

// examples/shards/run-local.sh: the shards as processes, the merge, and with CHECK=1 the
// comparison with one plain generate, which it exits non-zero on.
TEST_F(ShardCli, TheLocalShardScriptMergesIntoTheFileOfOneRun) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path merged = dir_ / "merged.json", whole = dir_ / "whole.json";
  const int code = shell("cd " + quoted(dir_.string()) +
                         " && SHADOWGEN=" + quoted(SHADOWGEN_EXECUTABLE) + " CHECK=1 JOBS=2 bash " +
                         quoted(std::string(SHADOWGEN_EXAMPLES_DIR) + "/shards/run-local.sh") +
                         " yard.json 4 merged.json >run/out 2>run/err");
  ASSERT_EQ(code, 0) << contents(dir_ / "run" / "err");
  const std::string said = contents(dir_ / "run" / "out") + contents(dir_ / "run" / "err");
  EXPECT_NE(said.find("is byte for byte the database of one plain generate"), std::string::npos)
      << said;
  // The same as a run of this test's own, the scene named by another path but for that.
  ASSERT_EQ(run({"generate", scene.string(), "-o", whole.string()}).code, 0);
  std::string expected = contents(whole);
  for (std::size_t at; (at = expected.find(scene.string())) != std::string::npos;) {
    expected.replace(at, scene.string().size(), "yard.json");
  }
  EXPECT_EQ(contents(merged), expected);
  EXPECT_EQ(files(), std::vector<std::string>({"merged.json", "whole.json", "yard.json"}));
}

TEST_F(ShardCli, ABadShareIsAUsageError) {
  const fs::path scene = write("yard.json", kYard);
  for (const char* share : {"0/3", "4/3", "1/0", "3", "a/b", "1/2/3", "-1/2", "1/2000000"}) {
    const Outcome o =
        run({"generate", scene.string(), "-o", (dir_ / "s.json").string(), "--instants", share});
    EXPECT_EQ(o.code, 2) << share;
    EXPECT_NE(o.err.find("--instants " + std::string(share) +
                         ": expected K/N, shard K of N, 1 <= K <= N <= 1000000"),
              std::string::npos)
        << o.err;
  }
  const Outcome kept = run({"generate", scene.string(), "-o", (dir_ / "s.json").string(),
                            "--instants", "1/2", "--keep-instants"});
  EXPECT_EQ(kept.code, 2);
  EXPECT_EQ(files(), std::vector<std::string>{"yard.json"});
}

TEST_F(ShardCli, ASceneWithoutASunPathHasNothingToShare) {
  const fs::path scene = write("lamp.json", R"({"format": "shadowgen-scene/1",
      "polygons": [{"id": "g", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
      "lights": [{"id": "lamp", "type": "point", "position": [0, 0, 3]}]})");
  const Outcome o =
      run({"generate", scene.string(), "-o", (dir_ / "s.json").string(), "--instants", "1/2"});
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.err, "shadowgen: " + scene.string() +
                       ": --instants shares out the instants of sun paths, and the scene has no "
                       "sun path (a `sun` light with from, to and step_min)\n");
  EXPECT_EQ(files(), std::vector<std::string>{"lamp.json"});
}

TEST_F(ShardCli, OnlyMergeReadsAShard) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path one = shard(scene, 1, 2);
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"report", one.string()},
        {"report", one.string(), "--format", "sun-hours"},
        {"export", one.string(), "--obj", (dir_ / "x.obj").string()},
        {"render", one.string(), "--eye", "5,-20,10", "--target", "5,5,0", "--svg",
         (dir_ / "x.svg").string()}}) {
    const Outcome o = run(command);
    EXPECT_EQ(o.code, 1) << command[0];
    EXPECT_EQ(o.err, "shadowgen: " + one.string() +
                         ": is shard 1 of 2 of a sun-path run (generate --instants K/N), not a "
                         "whole shadowed database: join every shard with shadowgen merge first\n")
        << command[0];
  }
  EXPECT_EQ(files(), std::vector<std::string>({"shard-1.json", "yard.json"}));
}

TEST_F(ShardCli, MergeRefusesShardsThatAreNotOneWholeRun) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path one = shard(scene, 1, 3), two = shard(scene, 2, 3), three = shard(scene, 3, 3);
  const fs::path out = dir_ / "merged.json";

  const Outcome missing = run({"merge", one.string(), three.string(), "-o", out.string()});
  EXPECT_EQ(missing.code, 1);
  EXPECT_EQ(missing.err, "shadowgen: " + one.string() +
                             ": shards 2 of 3 are missing: merge needs every shard of the run\n");

  const Outcome twice =
      run({"merge", one.string(), two.string(), two.string(), three.string(), "-o", out.string()});
  EXPECT_EQ(twice.code, 1);
  EXPECT_EQ(twice.err,
            "shadowgen: " + two.string() + ": is shard 2 of 3, as " + two.string() + " is\n");

  const Outcome scene_given = run({"merge", scene.string(), one.string(), "-o", out.string()});
  EXPECT_EQ(scene_given.code, 1);
  EXPECT_NE(scene_given.err.find("shadowgen: " + scene.string() + ": \"format\" is "),
            std::string::npos)
      << scene_given.err;

  const Outcome onto_input =
      run({"merge", one.string(), two.string(), three.string(), "-o", three.string()});
  EXPECT_EQ(onto_input.code, 2);

  // A shard whose first node does not start its run of blocks (blocks 1 and 2 of 0 to 4).
  std::string text = contents(two);
  const std::string key = "\"block\": 1,";
  ASSERT_NE(text.find(key), std::string::npos);
  text.replace(text.find(key), key.size(), "\"block\": 2,");
  write("shard-2.json", text);
  const Outcome moved =
      run({"merge", one.string(), two.string(), three.string(), "-o", out.string()});
  EXPECT_EQ(moved.code, 1);
  EXPECT_NE(moved.err.find("shadowgen: " + two.string() + ": face 'yard': "), std::string::npos)
      << moved.err;
  EXPECT_NE(moved.err.find("expected the tree's node that starts at block 1 of the shard's "
                           "blocks 1 to 3"),
            std::string::npos)
      << moved.err;
  EXPECT_EQ(files(), std::vector<std::string>(
                         {"shard-1.json", "shard-2.json", "shard-3.json", "yard.json"}));
}

// Each shard holds its own share (docs/scene-format.md, "Shards of a sun path"): lit
// polygons of the lights that are no instant in shard 1 alone, an instant's lit area alone
// in any. A shard holding more is refused naming it, the face and the light, and nothing
// is written: merge once took such polygons from no shard but the first, silently.
TEST_F(ShardCli, MergeRefusesAShardHoldingWhatIsNotItsShare) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path one = shard(scene, 1, 3), two = shard(scene, 2, 3), three = shard(scene, 3, 3);
  const fs::path out = dir_ / "merged.json";
  const nlohmann::json first = nlohmann::json::parse(contents(one));
  const nlohmann::json second = nlohmann::json::parse(contents(two));
  ASSERT_EQ(first["faces"][0]["id"], "yard");
  ASSERT_FALSE(first["faces"][0]["lit"]["lamp"].empty());

  nlohmann::json lamp_in_second = second;
  lamp_in_second["faces"][0]["lit"]["lamp"] = first["faces"][0]["lit"]["lamp"];
  write("shard-2.json", lamp_in_second.dump());
  const Outcome lamp =
      run({"merge", one.string(), two.string(), three.string(), "-o", out.string()});
  EXPECT_EQ(lamp.code, 1);
  EXPECT_EQ(lamp.err, "shadowgen: " + two.string() +
                          ": face 'yard': faces[0].lit['lamp']: is shard 2 of 3, which holds no "
                          "lit polygons: the lights that are no instant of a sun path are lit in "
                          "shard 1 alone\n");

  nlohmann::json kept = second;
  kept["sun_paths"][0]["instant_polygons"] = "kept";
  write("shard-2.json", kept.dump());
  const Outcome polygons_kept =
      run({"merge", one.string(), two.string(), three.string(), "-o", out.string()});
  EXPECT_EQ(polygons_kept.code, 1);
  EXPECT_EQ(polygons_kept.err,
            "shadowgen: " + two.string() +
                ": sun path 'march21': sun_paths[0] ('march21').instant_polygons: a shard keeps "
                "its instants' lit areas alone: \"instant_polygons\" must be \"dropped\" "
                "(generate --instants does not take --keep-instants)\n");
  EXPECT_EQ(files(), std::vector<std::string>(
                         {"shard-1.json", "shard-2.json", "shard-3.json", "yard.json"}));
}

}  // namespace
}  // namespace shadowgen::test
