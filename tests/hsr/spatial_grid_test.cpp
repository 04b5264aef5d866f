#include "hsr/spatial_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <vector>

#include "tests/hsr/scenes.h"

namespace shadowgen::hsr {
namespace {

// A grid over the boxes' extent holding each box as the item of its index.
SpatialGrid grid_of(const std::vector<clipper::Box2>& boxes) {
  clipper::Box2 extent;
  for (const clipper::Box2& b : boxes) extent.add(b);
  SpatialGrid grid(extent, boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) grid.insert(k, boxes[k]);
  return grid;
}

// Every box that overlaps the query comes back (the grid is a superset), once from
// query and, after sorting out repeats, as the very same set from query_shared.
TEST(SpatialGrid, SharedQueriesFindWhatQueriesFind) {
  const std::vector<clipper::Box2> boxes = test::random_image_boxes(7, 2000, 50);
  SpatialGrid grid = grid_of(boxes);
  const SpatialGrid& shared = grid;

  for (const clipper::Box2& query : test::random_image_boxes(8, 200, 20)) {
    std::vector<std::size_t> once, repeated;
    grid.query(query, once);
    shared.query_shared(query, repeated);
    std::vector<std::size_t> sorted_once = once;
    std::sort(sorted_once.begin(), sorted_once.end());
    EXPECT_EQ(std::adjacent_find(sorted_once.begin(), sorted_once.end()), sorted_once.end());
    std::sort(repeated.begin(), repeated.end());
    repeated.erase(std::unique(repeated.begin(), repeated.end()), repeated.end());
    EXPECT_EQ(sorted_once, repeated);
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      if (boxes[k].overlaps(query)) {
        EXPECT_TRUE(std::binary_search(repeated.begin(), repeated.end(), k));
      }
    }
  }
}

// Erased items never come back, from either query; the others come as they came before
// the erasing, query after query (the first query drops the erased entries of the cells
// it passes): the wide list first, reordered by its erasures, then the cells' items in
// the same order.
TEST(SpatialGrid, ErasedItemsAreGoneAndTheOthersKeepTheirOrder) {
  const std::vector<clipper::Box2> boxes = test::random_image_boxes(9, 2000, 50);
  SpatialGrid grid = grid_of(boxes);
  const std::vector<clipper::Box2> queries = test::random_image_boxes(10, 200, 20);
  std::vector<std::vector<std::size_t>> before;
  for (const clipper::Box2& query : queries) grid.query(query, before.emplace_back());

  std::vector<char> erased(boxes.size(), 0);
  for (std::size_t k = 0; k < boxes.size(); k += 3) {
    grid.erase(k);
    erased[k] = 1;
  }
  grid.erase(boxes.size() + 5);  // never inserted: nothing to forget
  std::size_t seen = 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t q = 0; q < queries.size(); ++q) {
      std::vector<std::size_t> expected;
      std::copy_if(before[q].begin(), before[q].end(), std::back_inserter(expected),
                   [&](std::size_t k) { return !erased[k]; });
      std::vector<std::size_t> got, shared;
      grid.query(queries[q], got);
      const auto wide = [&](std::size_t k) { return grid.is_wide(boxes[k]); };
      const auto got_cells = std::find_if_not(got.begin(), got.end(), wide);
      const auto expected_cells = std::stable_partition(expected.begin(), expected.end(), wide);
      EXPECT_TRUE(std::is_permutation(got.begin(), got_cells, expected.begin(), expected_cells))
          << "query " << q << ", pass " << pass;
      EXPECT_TRUE(std::equal(got_cells, got.end(), expected_cells, expected.end()))
          << "query " << q << ", pass " << pass;
      static_cast<const SpatialGrid&>(grid).query_shared(queries[q], shared);
      std::sort(shared.begin(), shared.end());
      shared.erase(std::unique(shared.begin(), shared.end()), shared.end());
      std::sort(expected.begin(), expected.end());
      EXPECT_EQ(shared, expected) << "query " << q << ", pass " << pass;
      seen += got.size();
    }
  }
  EXPECT_GT(seen, 1000u);
}

}  // namespace
}  // namespace shadowgen::hsr
