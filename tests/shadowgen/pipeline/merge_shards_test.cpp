// Shards of a sun-path run joined (shadowgen/pipeline/merge_shards.h): byte for byte the
// database of one run, for any number of shards and threads; and every way the shards can
// fail to be one whole run, refused naming the file.

#include "shadowgen/pipeline/merge_shards.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/scene/database_reader.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

// The courtyard over 21 March every 10 minutes (72 instants, 5 blocks), with a lamp that
// is no instant, and a face of two parts (a bent roof over the wall).
std::string scene_json() {
  std::string json =
      test::site_scene(test::kCourtyard + R"(,
      {"id": "bent", "outer": [[-9,-7,3],[-7,-7,3],[-7,-1,3.5],[-9,-1,3]]})",
                       R"("from": "2026-03-21T06:00", "to": "2026-03-21T18:00", "step_min": 10)");
  const std::string lights = R"("lights": [)";
  json.insert(json.find(lights) + lights.size(),
              R"({"id": "lamp", "type": "point", "position": [0, -5, 3]}, )");
  return json;
}

Scene scene() { return parse_scene(scene_json(), "court.json").scene; }

// Shard k of n, written and read back as merge reads it.
ShardFile shard(const Scene& scene, std::size_t k, std::size_t n, unsigned threads = 1) {
  GenerateOptions options;
  options.threads = threads;
  options.shard = ShardPlace{k, n};
  const std::string file = "shard" + std::to_string(k + 1) + ".json";
  return {file, parse_database(database_json(generate_shadows(scene, options).shadowed), file)};
}

std::vector<ShardFile> shards(const Scene& scene, std::size_t n) {
  std::vector<ShardFile> out;
  for (std::size_t k = 0; k < n; ++k) out.push_back(shard(scene, k, n));
  return out;
}

TEST(MergeShards, AnyNumberOfShardsGivesTheDatabaseOfOneRunByteForByte) {
  const Scene court = scene();
  GenerateOptions options;
  options.threads = 2;
  const std::string one_run = database_json(generate_shadows(court, options).shadowed);
  ASSERT_NE(one_run.find("\"lamp\""), std::string::npos);
  // 1 to 5 shards of 5 blocks, and more shards than blocks (some hold no instant).
  for (const std::size_t n : {1u, 2u, 3u, 5u, 7u}) {
    std::vector<ShardFile> files = shards(court, n);
    std::swap(files.front(), files.back());  // any order
    EXPECT_EQ(database_json(merge_shards(std::move(files))), one_run) << n << " shards";
  }
}

TEST(MergeShards, AShardHoldsItsOwnInstantsAndTheOtherLightsOnlyInTheFirst) {
  const Scene court = scene();
  const ShardFile first = shard(court, 0, 3), second = shard(court, 1, 3);
  const SunPathHours& path = second.shadowed.sun_paths.at(0);
  EXPECT_EQ(path.instants.size(), 72u);  // 06:10 to 18:00
  EXPECT_EQ(path.shard_first, 16u);      // blocks 1 of 0..4
  EXPECT_EQ(path.shard_last, 48u);       // and 2
  EXPECT_EQ(path.lit_area.at(0).size(), 32u);
  EXPECT_TRUE(path.regions.empty());
  std::size_t lamp_polygons = 0, lamp_in_second = 0;
  for (std::size_t f = 0; f < court.faces.size(); ++f) {
    lamp_polygons += first.shadowed.lit()[f][0].size();
    lamp_in_second += second.shadowed.lit()[f][0].size();
  }
  EXPECT_GT(lamp_polygons, 0u);
  EXPECT_EQ(lamp_in_second, 0u);
}

std::string merge_error(std::vector<ShardFile> files) {
  try {
    merge_shards(std::move(files));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MergeShards, RefusesAnythingButEveryShardOfOneRunOnce) {
  const Scene court = scene();
  std::vector<ShardFile> files = shards(court, 3);

  std::vector<ShardFile> missing = {files[0], files[2]};
  EXPECT_EQ(merge_error(missing),
            "shard1.json: shards 2 of 3 are missing: merge needs every "
            "shard of the run");

  std::vector<ShardFile> twice = {files[0], files[1], files[1], files[2]};
  EXPECT_EQ(merge_error(twice), "shard2.json: is shard 2 of 3, as shard2.json is");

  std::vector<ShardFile> other_count = {files[0], shard(court, 1, 2)};
  EXPECT_EQ(merge_error(other_count), "shard2.json: is shard 2 of 2, shard1.json one of 3");

  Scene moved = court;
  moved.faces[0].parts[0].outer[0].x -= 1.0;
  std::vector<ShardFile> other_scene = {files[0], shard(moved, 1, 3), files[2]};
  EXPECT_EQ(merge_error(other_scene),
            "shard2.json: is a shard of another scene than shard1.json (its faces, lights, "
            "views or sun paths differ)");

  GenerateOptions whole;
  whole.threads = 1;
  std::vector<ShardFile> not_a_shard = {
      {"court.shadowed.json", generate_shadows(court, whole).shadowed}};
  EXPECT_EQ(merge_error(not_a_shard),
            "court.shadowed.json: is a whole shadowed database, not a shard of a run cut by "
            "generate --instants K/N");

  // Sums that do not fit their face: a part that the face does not have.
  std::vector<ShardFile> tampered = files;
  for (SunHoursNode& node : tampered[1].shadowed.sun_paths[0].nodes[0]) {
    if (!node.sums.parts.empty()) node.sums.parts[0].part = 5;
  }
  const std::string message = merge_error(tampered);
  EXPECT_NE(message.find("shard2.json: face 'ground': sun path 'day': "), std::string::npos)
      << message;
  EXPECT_NE(message.find("part 5 where part 0 was expected"), std::string::npos) << message;

  // Sums of the right form whose pieces lie off their face: the joined regions fail the
  // checks of a database read.
  std::vector<ShardFile> moved_off = files;
  bool moved_one = false;
  for (SunHoursNode& node : moved_off[1].shadowed.sun_paths[0].nodes[0]) {
    if (node.sums.parts.empty()) continue;
    for (clipper::Point2& p : node.sums.parts[0].counts.back().pieces[0].outer) p.x += 100.0;
    moved_one = true;
    break;
  }
  ASSERT_TRUE(moved_one);
  const std::string off = merge_error(moved_off);
  EXPECT_NE(off.find("shard1.json: face 'ground': the shards joined do not make a valid "
                     "database: "),
            std::string::npos)
      << off;
}

}  // namespace
}  // namespace shadowgen
