#pragma once

// The candidate-pair sweep shared by the clipper's noding steps: every pair of edges
// whose boxes, each grown by a margin, overlap. A sweep over x with y-interval
// rejection, O(n log n + m) for m pairs whose x-ranges overlap.

#include <algorithm>
#include <cstddef>
#include <vector>

#include "boundary_graph.h"

namespace shadowgen::clipper::detail {

// Calls visit(i, j) (i, j indices into `edges`, in either order) for every pair whose
// boxes, each grown by margin(i), overlap and of which at least one is selected
// (select(i)).
template <typename Edges, typename Margin, typename Select, typename Visit>
void for_each_close_pair(const Edges& edges, Margin margin, Select select, Visit visit) {
  struct Item {
    double xmin, xmax, ymin, ymax;
    std::size_t edge;
    bool selected;
  };
  std::vector<Item> items;
  items.reserve(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto& e = edges[i];
    const double d = margin(i);
    items.push_back({std::min(e.from.x, e.to.x) - d, std::max(e.from.x, e.to.x) + d,
                     std::min(e.from.y, e.to.y) - d, std::max(e.from.y, e.to.y) + d, i, select(i)});
  }
  std::sort(items.begin(), items.end(),
            [](const Item& a, const Item& b) { return a.xmin < b.xmin; });
  std::vector<const Item*> active;
  for (const Item& item : items) {
    std::size_t kept = 0;
    for (const Item* c : active) {
      // Kept unless left behind by the sweep (without branches: unpredictable).
      active[kept] = c;
      const bool live = c->xmax >= item.xmin;
      kept += live ? 1 : 0;
      if (live & (item.selected | c->selected) & (c->ymin <= item.ymax) & (item.ymin <= c->ymax)) {
        visit(c->edge, item.edge);
      }
    }
    active.resize(kept);
    active.push_back(&item);
  }
}

}  // namespace shadowgen::clipper::detail
