#pragma once

// How a sun path's instants are cut into blocks, and the blocks shared out among shards
// (generate --instants K/N). The blocks are the leaves of the tree in which the path's
// sums are joined (shadows/sun_hours_tree.h); the database reader and the generator both
// need to know which instants a shard holds, so it is said once, here.

#include <cstddef>

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

// Instants per block: enough that joining blocks costs little beside summing them, few
// enough that a day's path gives several blocks to share out.
constexpr std::size_t kInstantsPerBlock = 16;

// Blocks [first, last), or instants [first, last).
struct IndexRun {
  std::size_t first = 0, last = 0;
  std::size_t size() const { return last - first; }
};

// Blocks of a path of `instants` instants (the last one may be short).
std::size_t block_count(std::size_t instants);

// The blocks of shard `shard` (0-based) of `shards`: consecutive, shares as even as they
// can be, empty where there are fewer blocks than shards.
IndexRun shard_blocks(std::size_t blocks, std::size_t shard, std::size_t shards);

// The instants of shard `place` of a path of `instants` instants.
IndexRun shard_instants(std::size_t instants, const ShardPlace& place);

}  // namespace shadowgen
