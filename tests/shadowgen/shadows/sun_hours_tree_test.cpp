// The fixed tree of a sun path's sums (shadowgen/shadows/sun_hours_tree.h): the nodes a
// run of blocks makes, and joining nodes that cover the blocks once, and only so.

#include "shadowgen/shadows/sun_hours_tree.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "hsr/area.h"
#include "shadowgen/model/instant_blocks.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

struct Place {
  std::size_t first_block;
  unsigned level;
  friend bool operator==(const Place&, const Place&) = default;
};

std::vector<Place> places_after_pushing(std::size_t first, std::size_t last) {
  SunHoursNodes nodes;
  for (std::size_t b = first; b < last; ++b) nodes.push(b, std::nullopt);
  std::vector<Place> out;
  for (const SumsNode& node : nodes.take()) out.push_back({node.first_block, node.level});
  return out;
}

TEST(SunHoursTree, ARunOfBlocksMakesTheAlignedSubtreesThatCoverIt) {
  // Blocks 3 to 10: [3], [4, 8), [8, 10), [10], the segment tree's decomposition.
  EXPECT_EQ(places_after_pushing(3, 11), (std::vector<Place>{{3, 0}, {4, 2}, {8, 1}, {10, 0}}));
  // From block 0: the binary digits of the count, greatest first.
  EXPECT_EQ(places_after_pushing(0, 11), (std::vector<Place>{{0, 3}, {8, 1}, {10, 0}}));
  EXPECT_EQ(places_after_pushing(0, 16), (std::vector<Place>{{0, 4}}));
  EXPECT_TRUE(places_after_pushing(5, 5).empty());
}

TEST(SunHoursTree, BlocksMustComeInOrder) {
  SunHoursNodes nodes;
  nodes.push(2, std::nullopt);
  EXPECT_THROW(nodes.push(4, std::nullopt), std::logic_error);
}

TEST(SunHoursTree, NodesMustCoverEveryBlockOnce) {
  const auto nodes = [](std::vector<Place> places) {
    std::vector<SumsNode> out;
    for (const Place& p : places) out.push_back({p.first_block, p.level, std::nullopt});
    return out;
  };
  EXPECT_NO_THROW(join_nodes(nodes({{0, 2}, {4, 0}}), 5));
  EXPECT_NO_THROW(join_nodes(nodes({{4, 0}, {0, 2}}), 5));              // any order
  EXPECT_THROW(join_nodes(nodes({{0, 2}}), 5), std::invalid_argument);  // block 4 left out
  EXPECT_THROW(join_nodes(nodes({{0, 2}, {2, 1}, {4, 0}}), 5), std::invalid_argument);  // twice
  EXPECT_THROW(join_nodes(nodes({{1, 1}, {0, 0}, {3, 0}}), 4), std::invalid_argument);  // unaligned
  EXPECT_THROW(join_nodes(nodes({{0, 2}, {4, 0}, {5, 0}}), 5), std::invalid_argument);  // beyond
  EXPECT_FALSE(join_nodes({}, 0).has_value());
}

TEST(SunHoursTree, ShardsShareTheBlocksOutInOrderAndWhole) {
  for (const std::size_t blocks : {0u, 1u, 5u, 16u, 275u}) {
    for (const std::size_t shards : {1u, 2u, 3u, 7u, 300u}) {
      std::size_t next = 0;
      for (std::size_t k = 0; k < shards; ++k) {
        const IndexRun run = shard_blocks(blocks, k, shards);
        EXPECT_EQ(run.first, next) << blocks << " blocks, shard " << k << " of " << shards;
        EXPECT_LE(run.size(), blocks / shards + 1);
        next = run.last;
      }
      EXPECT_EQ(next, blocks);
    }
  }
  // Instants: a path of 40 instants has blocks of 16, 16 and 8.
  EXPECT_EQ(block_count(40), 3u);
  const IndexRun last = shard_instants(40, {2, 3});
  EXPECT_EQ(last.first, 32u);
  EXPECT_EQ(last.last, 40u);
}

// A face's sums joined from halves: the instants' lit areas times their step, summed over
// the regions, and the regions tiling the face, as when the instants are added one by one.
TEST(SunHoursTree, AbsorbingLaterSumsCountsEachPieceOnce) {
  const ShadowedScene shadowed =
      test::generated(test::site_scene(test::kCourtyard, test::kMarch21), /*threads=*/1);
  const SunPathHours& path = shadowed.sun_paths.at(0);
  ASSERT_GT(path.instants.size(), kInstantsPerBlock);  // several blocks: joined by absorb
  for (std::size_t f = 0; f < shadowed.scene().faces.size(); ++f) {
    double hour_area = 0.0, area = 0.0, lit_hours = 0.0;
    for (const SunHoursRegion& region : path.regions[f]) {
      area += lit_area(region.polygons);
      hour_area += region.hours * lit_area(region.polygons);
    }
    for (const double a : path.lit_area[f]) lit_hours += a * path.step_min / 60.0;
    const double face_area = hsr::area(shadowed.scene().faces[f].parts);
    EXPECT_NEAR(area, face_area, 1e-9 * face_area) << shadowed.scene().faces[f].id;
    EXPECT_NEAR(hour_area, lit_hours, 1e-9 * std::max(1.0, lit_hours))
        << shadowed.scene().faces[f].id;
  }
}

}  // namespace
}  // namespace shadowgen
