#pragma once

// Whether a large set of faces' ids are distinct, found in parallel: the check that
// claiming each id in a hash table, in turn, would make, without one thread hashing and
// storing every id of a city.

#include <span>

#include "shadowgen/model/scene.h"

namespace shadowgen::scene::detail {

// True when no two of `faces` have the same id. The ids are sorted (by pointer, in
// parallel on the calling task arena's threads) and neighbours compared: O(n log n)
// comparisons over the threads, O(n) memory. Says not which clash: a caller that must name
// it reads the ids again in order.
bool ids_distinct(std::span<const Face> faces);

}  // namespace shadowgen::scene::detail
