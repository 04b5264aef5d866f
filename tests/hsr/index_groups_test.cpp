#include "hsr/index_groups.h"

#include <gtest/gtest.h>

#include <vector>

namespace shadowgen::hsr {
namespace {

// Keys 2, 0, 2, 3, 0 under 5 keys: key 0 holds indices 1 and 4, key 1 none, key 2 holds 0
// and 2, key 3 holds 3, key 4 none; each group in index order.
TEST(IndexGroups, IndicesByKeyEachInOrder) {
  const std::vector<std::size_t> keys{2, 0, 2, 3, 0};
  const IndexGroups groups =
      index_groups(keys.size(), 5, [&keys](std::size_t i) { return keys[i]; });
  EXPECT_EQ(groups.starts, (std::vector<std::size_t>{0, 2, 2, 4, 5, 5}));
  EXPECT_EQ(groups.order, (std::vector<std::size_t>{1, 4, 0, 2, 3}));
  EXPECT_EQ(groups.first(2), 2u);
  EXPECT_EQ(groups.last(2), 4u);
  EXPECT_EQ(groups.first(1), groups.last(1));
}

TEST(IndexGroups, NoIndicesNoKeys) {
  const IndexGroups none = index_groups(0, 0, [](std::size_t) { return std::size_t{0}; });
  EXPECT_EQ(none.starts, (std::vector<std::size_t>{0}));
  EXPECT_TRUE(none.order.empty());
  const IndexGroups empty_keys = index_groups(0, 3, [](std::size_t) { return std::size_t{0}; });
  EXPECT_EQ(empty_keys.starts, (std::vector<std::size_t>{0, 0, 0, 0}));
}

}  // namespace
}  // namespace shadowgen::hsr
