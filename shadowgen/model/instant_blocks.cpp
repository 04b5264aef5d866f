#include "shadowgen/model/instant_blocks.h"

#include <algorithm>

namespace shadowgen {

std::size_t block_count(std::size_t instants) {
  return (instants + kInstantsPerBlock - 1) / kInstantsPerBlock;
}

IndexRun shard_blocks(std::size_t blocks, std::size_t shard, std::size_t shards) {
  return {blocks * shard / shards, blocks * (shard + 1) / shards};
}

IndexRun shard_instants(std::size_t instants, const ShardPlace& place) {
  const IndexRun blocks = shard_blocks(block_count(instants), place.index, place.count);
  return {std::min(instants, blocks.first * kInstantsPerBlock),
          std::min(instants, blocks.last * kInstantsPerBlock)};
}

}  // namespace shadowgen
