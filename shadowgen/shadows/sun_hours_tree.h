#pragma once

// The fixed tree in which a sun path's sums are joined, so that a path cut into shards
// (generate --instants K/N) and joined again (merge) gives the very sums of one run, bit
// for bit, whatever the number of shards and threads.
//
// The path's instants, in time order, go in blocks of kInstantsPerBlock
// (model/instant_blocks.h); a block's sums
// are its instants added one by one (FaceSunHours::add). The blocks are the leaves of a
// perfect binary tree of 2^h leaves (h the least with 2^h >= blocks); a node's sums are
// its left child's sums absorbing its right child's (FaceSunHours::absorb), a child past
// the last block counting nothing. Each sums is a deterministic function of its blocks,
// so any run that makes a node, in any process, makes the same one.
//
// A shard holds a run of consecutive blocks (shard_blocks) and makes the nodes that cover
// that run and nothing else, the greatest first: the aligned, complete subtrees of a
// segment tree's decomposition (at most 2h of them). Joining every shard's nodes
// (join_nodes) makes the rest of the tree as one run makes it.

#include <cstddef>
#include <optional>
#include <vector>

#include "shadowgen/model/instant_blocks.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/shadows/sun_hours.h"

namespace shadowgen {

// A node with its sums; none where its instants lit no part of the face.
struct SumsNode {
  std::size_t first_block = 0;
  unsigned level = 0;
  std::optional<FaceSunHours> sums;
};

// The nodes over a run of blocks of one face, made as the blocks come.
class SunHoursNodes {
 public:
  // Takes block `block`'s sums: the blocks must come in order, one after another.
  void push(std::size_t block, std::optional<FaceSunHours> sums);

  // The nodes covering the blocks pushed so far, greatest first. Only the run a shard
  // was given is covered by aligned subtrees when all its blocks are in.
  std::vector<SumsNode> take() { return std::move(nodes_); }

 private:
  std::vector<SumsNode> nodes_;
};

// The sums of the whole tree of `blocks` blocks from nodes covering every block once (any
// order). Throws std::invalid_argument where a block is covered twice or not at all, or
// a node is not one of the tree's. Throws clipper::SnapRoundingError as absorb does.
std::optional<FaceSunHours> join_nodes(std::vector<SumsNode> nodes, std::size_t blocks);

}  // namespace shadowgen
