#include "hsr/parallel.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace shadowgen::hsr {
namespace {

// Every index is called exactly once, on one thread and on several, and none when n is 0.
TEST(ForEachTakenInOrder, CallsEveryIndexOnce) {
  for (const int threads : {1, 2, 4}) {
    tbb::task_arena arena(threads);
    for (const std::size_t n :
         {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{1000}}) {
      std::vector<std::atomic<int>> calls(n);
      arena.execute([&] { for_each_taken_in_order(n, [&](std::size_t i) { ++calls[i]; }); });
      for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(calls[i].load(), 1) << threads << " " << i;
    }
  }
}

// Indices are taken in increasing order, whichever thread is free: the j-th call to start
// has an index of at most j + threads - 1 (the others' takes may be recorded late), where
// halving the range would start a second thread in its middle. The list schedule that
// puts the largest image regions first relies on it.
TEST(ForEachTakenInOrder, TakesIndicesInIncreasingOrder) {
  for (const int threads : {1, 2, 4}) {
    tbb::task_arena arena(threads);
    std::mutex mutex;
    std::vector<std::size_t> started;
    arena.execute([&] {
      for_each_taken_in_order(500, [&](std::size_t i) {
        {
          const std::lock_guard lock(mutex);
          started.push_back(i);
        }
        // Calls that take a while, as regions do, so that every thread joins in.
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      });
    });
    ASSERT_EQ(started.size(), 500u);
    for (std::size_t j = 0; j < started.size(); ++j) {
      EXPECT_LE(started[j], j + static_cast<std::size_t>(threads) - 1) << threads << " " << j;
    }
  }
}

}  // namespace
}  // namespace shadowgen::hsr
