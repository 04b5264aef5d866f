#include "hsr/spatial_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace shadowgen::hsr {
namespace {

// Boxes of every size over a 100 × 100 extent, some wide enough for the wide list.
std::vector<clipper::Box2> random_boxes(std::uint64_t seed, std::size_t count) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<clipper::Box2> boxes;
  for (std::size_t k = 0; k < count; ++k) {
    const double x = 100.0 * unit(random), y = 100.0 * unit(random);
    const double size = k % 50 == 0 ? 80.0 : 3.0 * unit(random);
    boxes.push_back({x, y, x + size, y + size});
  }
  return boxes;
}

// Every box that overlaps the query comes back (the grid is a superset), once from
// query and, after sorting out repeats, as the very same set from query_shared.
TEST(SpatialGrid, SharedQueriesFindWhatQueriesFind) {
  const std::vector<clipper::Box2> boxes = random_boxes(7, 2000);
  clipper::Box2 extent;
  for (const clipper::Box2& b : boxes) extent.add(b);
  SpatialGrid grid(extent, boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) grid.insert(k, boxes[k]);
  const SpatialGrid& shared = grid;

  for (const clipper::Box2& query : random_boxes(8, 200)) {
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
