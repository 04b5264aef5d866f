#pragma once

// Work spread over oneTBB's threads, with results that do not depend on them: each call
// writes only what belongs to its index, and the failure passed on is always the same.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <vector>

namespace shadowgen::hsr {

// Calls work(i) for every i in [0, n), in parallel on the threads of the calling task
// arena (every hardware thread unless a tbb::task_arena limits them); oneTBB's automatic
// partitioner groups indices into tasks, fewer for many cheap calls, one each for a few
// heavy ones when threads would idle. work(i) must write only what belongs to i. Where
// calls throw, all still run, and the exception of the lowest index is rethrown.
template <class Work>
void for_each_in_parallel(std::size_t n, Work&& work) {
  std::vector<std::exception_ptr> failures(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        try {
                          work(i);
                        } catch (...) {
                          failures[i] = std::current_exception();
                        }
                      }
                    });
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

// Calls work(i) for every i in [0, n), in parallel on the threads of the calling task
// arena, each thread taking the lowest index not yet taken whenever it is free: for n
// heavy calls ordered largest first, the last to start are the smallest (a list
// schedule), where for_each_in_parallel's halving would leave one thread the middle of
// the list. work(i) must not throw and must write only what belongs to i.
template <class Work>
void for_each_taken_in_order(std::size_t n, Work&& work) {
  std::atomic<std::size_t> next{0};
  const std::size_t takers =
      std::min(n, static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()));
  tbb::parallel_for(std::size_t{0}, takers, [&](std::size_t) {
    for (std::size_t i = next.fetch_add(1); i < n; i = next.fetch_add(1)) work(i);
  });
}

}  // namespace shadowgen::hsr
