#pragma once

// A uniform grid over image-space bounding boxes: which pieces may overlap a template
// (hidden-surface removal) or a receiver (shadow generation's coplanar faces).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "clipper/box.h"

namespace shadowgen::hsr {

class SpatialGrid {
 public:
  // A grid of about `expected_items` cells over `extent`. Items wider than kMaxCells
  // cells are kept on a separate list that every query returns, so one huge polygon (a
  // ground plane) does not fill every cell again each time it is clipped.
  SpatialGrid(const clipper::Box2& extent, std::size_t expected_items);

  void insert(std::size_t item, const clipper::Box2& box);
  // Forgets an item: no query returns it again. Its cell entries go when a query next
  // passes them (an area sort kills most pieces it inserts, and their entries outnumbered
  // the live ones ten to one where they were left for the caller to skip).
  void erase(std::size_t item);
  // Appends, once each, the items not erased whose cells meet `box` (a superset of the
  // overlapping): the wide list's (an erasure moves its last item into the gap), then the
  // cells' in row order, each cell's in the order they were inserted.
  void query(const clipper::Box2& box, std::vector<std::size_t>& out);
  // The same without the once-each bookkeeping or the clearing of erased entries, so that
  // several threads may query at once: an item whose box spans several cells comes once
  // per cell.
  void query_shared(const clipper::Box2& box, std::vector<std::size_t>& out) const;

  // True when `box` would go to the wide list.
  bool is_wide(const clipper::Box2& box) const;
  // Rectangles of block × block cells, aligned with the grid, covering `box`: cutting a
  // wide polygon along them keeps each piece local.
  std::vector<clipper::Box2> tiles(const clipper::Box2& box, int block) const;

 private:
  static constexpr std::size_t kMaxCells = 64;
  bool cell_range(const clipper::Box2& box, int& x0, int& y0, int& x1, int& y1) const;

  clipper::Box2 extent_;
  int nx_ = 1, ny_ = 1;
  double sx_ = 1.0, sy_ = 1.0;
  std::vector<std::vector<std::size_t>> cells_;
  std::vector<std::size_t> wide_;
  std::vector<std::uint32_t> seen_;
  std::vector<bool> is_wide_;
  std::vector<char> erased_;
  std::uint32_t stamp_ = 0;
};

}  // namespace shadowgen::hsr
