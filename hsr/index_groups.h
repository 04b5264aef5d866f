#pragma once

// Indices grouped by a small whole-number key, each group in index order: a counting sort,
// linear in the indices and the keys, where a stable sort of the items themselves would
// move every item O(log n) times on one thread.

#include <cstddef>
#include <vector>

namespace shadowgen::hsr {

struct IndexGroups {
  // Group k is order[starts[k]] ... order[starts[k + 1] - 1], ascending; keys + 1 entries.
  std::vector<std::size_t> starts;
  std::vector<std::size_t> order;

  std::size_t first(std::size_t key) const { return starts[key]; }
  std::size_t last(std::size_t key) const { return starts[key + 1]; }
};

// The indices [0, n) grouped by key(i), which must be below `keys`.
template <class Key>
IndexGroups index_groups(std::size_t n, std::size_t keys, Key&& key) {
  IndexGroups groups;
  groups.starts.assign(keys + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++groups.starts[key(i) + 1];
  for (std::size_t k = 0; k < keys; ++k) groups.starts[k + 1] += groups.starts[k];
  groups.order.resize(n);
  std::vector<std::size_t> next(groups.starts.begin(), groups.starts.end() - 1);
  for (std::size_t i = 0; i < n; ++i) groups.order[next[key(i)]++] = i;
  return groups;
}

}  // namespace shadowgen::hsr
