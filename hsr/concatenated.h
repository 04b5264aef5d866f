#pragma once

// Lists joined into one, in order, their elements moved on the calling task arena's
// threads: the same vector as appending the lists in turn, whatever the threads, without
// one thread moving every element of a large result.

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

#include "hsr/parallel.h"

namespace shadowgen::hsr {

// The elements of lists[0], then of lists[1], ..., moved into one vector; `lists` is left
// empty. T must be default-constructible and move-assignable: the result is made of
// default elements first (one cheap pass), then each list is moved into its place, and
// its moved-from husks freed, in parallel. O(total + lists.size()).
template <class T>
std::vector<T> concatenated(std::vector<std::vector<T>> lists) {
  std::vector<std::size_t> starts(lists.size() + 1, 0);
  for (std::size_t i = 0; i < lists.size(); ++i) starts[i + 1] = starts[i] + lists[i].size();
  std::vector<T> out(starts.back());
  for_each_in_parallel(lists.size(), [&](std::size_t i) {
    std::move(lists[i].begin(), lists[i].end(),
              out.begin() + static_cast<std::ptrdiff_t>(starts[i]));
    lists[i] = std::vector<T>();
  });
  return out;
}

}  // namespace shadowgen::hsr
