#include "hsr/concatenated.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <memory>
#include <vector>

namespace shadowgen::hsr {
namespace {

TEST(Concatenated, ListsInOrderEmptyOnesSkipped) {
  EXPECT_TRUE(concatenated(std::vector<std::vector<int>>{}).empty());
  EXPECT_TRUE(concatenated(std::vector<std::vector<int>>{{}, {}}).empty());
  EXPECT_EQ(concatenated(std::vector<std::vector<int>>{{4, 1}, {}, {7}, {2, 2, 9}}),
            (std::vector<int>{4, 1, 7, 2, 2, 9}));
}

// Elements are moved, not copied (a move-only type passes), and the result is the same on
// one thread and on several: list i of 1,000 holds i, i + 1, ..., i + i % 7 - 1.
TEST(Concatenated, MovesElementsTheSameOnAnyThreads) {
  const auto lists = [] {
    std::vector<std::vector<std::unique_ptr<int>>> out(1000);
    for (int i = 0; i < 1000; ++i) {
      for (int k = 0; k < i % 7; ++k) out[i].push_back(std::make_unique<int>(i + k));
    }
    return out;
  };
  std::vector<int> expected;
  for (int i = 0; i < 1000; ++i) {
    for (int k = 0; k < i % 7; ++k) expected.push_back(i + k);
  }
  for (int threads : {1, 4}) {
    tbb::task_arena arena(threads);
    const std::vector<std::unique_ptr<int>> joined =
        arena.execute([&] { return concatenated(lists()); });
    std::vector<int> values;
    for (const auto& p : joined) values.push_back(*p);
    EXPECT_EQ(values, expected) << threads << " threads";
  }
}

}  // namespace
}  // namespace shadowgen::hsr
