// The shadowed database's two layouts end to end (shadowgen/database/database_format.h):
// every output computed from a database is the same, byte for byte, whether the database
// was written with its polygons' coordinates inline (shadowgen-shadowed/1, as shadowgen
// wrote it before) or over each face's shared vertices (shadowgen-shadowed/2), shards
// merged included; and the shared vertices make the file smaller.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadowgen/output/database.h"
#include "shadowgen/scene/database_reader.h"
#include "tests/cli/cli_harness.h"

namespace shadowgen::test {
namespace {

const fs::path kScenes = fs::path(SHADOWGEN_EXAMPLES_DIR) / "scenes";

class DatabaseLayoutCli : public CliFolderTest<> {
 protected:
  DatabaseLayoutCli() : CliFolderTest("shadowgen-db-layout") {}

  // `database` (as generate writes it) written again in the inline layout, as `name`.
  fs::path inline_copy(const fs::path& database, const std::string& name) const {
    const fs::path out = dir_ / name;
    write_file(out, database_json(read_database(database), database::Layout::kInline));
    return out;
  }
};

TEST_F(DatabaseLayoutCli, EveryOutputIsTheSameFromEitherLayout) {
  const fs::path indexed = dir_ / "garden.shadowed.json";
  ASSERT_EQ(run({"generate", (kScenes / "garden.json").string(), "-o", indexed.string()}).code, 0);
  ASSERT_EQ(contents(indexed).rfind(R"({
  "format": "shadowgen-shadowed/2",)",
                                    0),
            0u);
  const fs::path inlined = inline_copy(indexed, "garden.inline.json");
  ASSERT_EQ(contents(inlined).rfind(R"({
  "format": "shadowgen-shadowed/1",)",
                                    0),
            0u);
  EXPECT_LT(contents(indexed).size(), contents(inlined).size());

  const fs::path svg = dir_ / "out.svg", obj = dir_ / "out.obj", glb = dir_ / "out.glb",
                 png = dir_ / "out.png";
  const std::vector<std::pair<std::vector<std::string>, fs::path>> outputs = {
      {{"report", "DB"}, {}},
      {{"report", "DB", "--format", "json"}, {}},
      {{"report", "DB", "--format", "sun-hours"}, {}},
      {{"report", "DB", "--format", "sun-hours-table"}, {}},
      {{"render", "DB", "--view", "main", "--svg", svg.string()}, svg},
      {{"render", "DB", "--view", "main", "--sun-hours", "march21", "--svg", svg.string()}, svg},
      {{"render", "DB", "--view", "main", "--png", png.string(), "--width", "64", "--height", "48"},
       png},
      {{"export", "DB", "--obj", obj.string()}, obj},
      {{"export", "DB", "--obj", obj.string(), "--sun-hours", "march21"}, obj},
      {{"export", "DB", "--gltf", glb.string(), "--sun-hours", "march21"}, glb},
  };
  for (const auto& [command, file] : outputs) {
    const std::string from_indexed = output(command, indexed, file);
    EXPECT_FALSE(from_indexed.empty()) << command[0] << " " << command.back();
    EXPECT_EQ(output(command, inlined, file), from_indexed) << command[0] << " " << command.back();
  }
  // Read back and written again, either layout gives the file generate wrote.
  EXPECT_EQ(database_json(read_database(inlined)), contents(indexed));
  EXPECT_EQ(database_json(read_database(indexed)), contents(indexed));
}

TEST_F(DatabaseLayoutCli, ShardsOfEitherLayoutMergeIntoTheFileOfOneRun) {
  const fs::path scene = kScenes / "garden.json";
  const fs::path whole = dir_ / "whole.json", merged = dir_ / "merged.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", whole.string()}).code, 0);
  std::vector<std::string> args = {"merge"};
  for (const int k : {1, 2}) {
    const fs::path shard = dir_ / ("shard-" + std::to_string(k) + ".json");
    ASSERT_EQ(run({"generate", scene.string(), "-o", shard.string(), "--instants",
                   std::to_string(k) + "/2"})
                  .code,
              0);
    // Shard 1 in the inline layout, shard 2 as written: merge takes either.
    args.push_back(k == 1 ? inline_copy(shard, "shard-1.inline.json").string() : shard.string());
  }
  args.insert(args.end(), {"-o", merged.string()});
  const Outcome o = run(args);
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(contents(merged), contents(whole));
}

}  // namespace
}  // namespace shadowgen::test
