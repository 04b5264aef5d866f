#pragma once

// Keeping some of a list's items, as a selection of lights keeps them: the scene's lights,
// a sampled method's rows of lit areas.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace shadowgen {

// Keeps the items of `items` marked in `keep` (one flag per item), in order. Throws
// std::invalid_argument where `keep` has another length.
template <class T>
void keep_marked(std::vector<T>& items, const std::vector<bool>& keep) {
  if (keep.size() != items.size()) {
    throw std::invalid_argument("keep_marked: " + std::to_string(keep.size()) + " flags for " +
                                std::to_string(items.size()) + " items");
  }
  std::vector<T> kept;
  kept.reserve(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (keep[k]) kept.push_back(std::move(items[k]));
  }
  items = std::move(kept);
}

}  // namespace shadowgen
