#include "hsr/spatial_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "tests/hsr/scenes.h"

namespace shadowgen::hsr {
namespace {

// Every box that overlaps the query comes back (the grid is a superset), once from
// query and, after sorting out repeats, as the very same set from query_shared.
TEST(SpatialGrid, SharedQueriesFindWhatQueriesFind) {
  const std::vector<clipper::Box2> boxes = test::random_image_boxes(7, 2000, 50);
  clipper::Box2 extent;
  for (const clipper::Box2& b : boxes) extent.add(b);
  SpatialGrid grid(extent, boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) grid.insert(k, boxes[k]);
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

}  // namespace
}  // namespace shadowgen::hsr
