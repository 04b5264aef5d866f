#include "shadowgen/shadows/sun_hours_tree.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace shadowgen {
namespace {

std::size_t span_of(unsigned level) { return std::size_t{1} << level; }

// The sums of a node from its children's: the left absorbs the right; a child that
// counts nothing leaves the other as it is.
std::optional<FaceSunHours> joined(std::optional<FaceSunHours> left,
                                   const std::optional<FaceSunHours>& right) {
  if (!right) return left;
  if (!left) return right;
  left->absorb(*right);
  return left;
}

}  // namespace

void SunHoursNodes::push(std::size_t block, std::optional<FaceSunHours> sums) {
  if (!nodes_.empty()) {
    const SumsNode& last = nodes_.back();
    if (last.first_block + span_of(last.level) != block) {
      throw std::logic_error("sun-hours blocks out of order");
    }
  }
  nodes_.push_back({block, 0, std::move(sums)});
  // Two neighbours of one level whose left one starts a subtree of the next level are
  // that subtree's children.
  while (nodes_.size() >= 2) {
    SumsNode& right = nodes_.back();
    SumsNode& left = nodes_[nodes_.size() - 2];
    if (left.level != right.level || left.first_block % span_of(left.level + 1) != 0) break;
    left.sums = joined(std::move(left.sums), right.sums);
    ++left.level;
    nodes_.pop_back();
  }
}

std::optional<FaceSunHours> join_nodes(std::vector<SumsNode> nodes, std::size_t blocks) {
  std::map<std::pair<unsigned, std::size_t>, std::optional<FaceSunHours>> by_place;
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (SumsNode& node : nodes) {
    if (node.level >= 64 || node.first_block % span_of(node.level) != 0 ||
        node.first_block >= blocks) {
      throw std::invalid_argument("sun-hours node of level " + std::to_string(node.level) +
                                  " at block " + std::to_string(node.first_block) +
                                  " is not a node of the tree of " + std::to_string(blocks) +
                                  " blocks");
    }
    runs.emplace_back(node.first_block, std::min(blocks, node.first_block + span_of(node.level)));
    by_place[{node.level, node.first_block}] = std::move(node.sums);
  }
  std::sort(runs.begin(), runs.end());
  std::size_t covered = 0;
  for (const auto& [first, last] : runs) {
    if (first != covered) {
      throw std::invalid_argument(
          "sun-hours nodes " +
          std::string(first < covered ? "cover a block twice" : "leave a block out") +
          " at block " + std::to_string(std::min(first, covered)));
    }
    covered = last;
  }
  if (covered != blocks) {
    throw std::invalid_argument("sun-hours nodes leave blocks from " + std::to_string(covered) +
                                " out");
  }
  if (blocks == 0) return std::nullopt;
  unsigned top = 0;
  while (span_of(top) < blocks) ++top;
  // Depth first, as a run pushing every block makes the same nodes.
  const auto node = [&](const auto& self, unsigned level,
                        std::size_t first) -> std::optional<FaceSunHours> {
    if (first >= blocks) return std::nullopt;
    const auto at = by_place.find({level, first});
    if (at != by_place.end()) return std::move(at->second);
    std::optional<FaceSunHours> left = self(self, level - 1, first);
    return joined(std::move(left), self(self, level - 1, first + span_of(level - 1)));
  };
  return node(node, top, 0);
}

}  // namespace shadowgen
