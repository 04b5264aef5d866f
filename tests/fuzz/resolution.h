#pragma once

// The clipper's resolution (docs/clipper.md, "Exactness and tolerance"): a vertex within the snap
// distance of an edge (detail/snap.h: 8u·|edge| + 2u·|P|) is taken as lying on it. Such a
// vertex meets the edge as far as the clipper can tell, so a piece between them may
// vanish the way a piece cut by rounded crossings may. All pairs, O(n²): fuzz inputs are
// small.

#include <cstddef>
#include <vector>

#include "clipper/detail/snap.h"
#include "clipper/polygon.h"
#include "clipper/predicates.h"

namespace shadowgen::fuzz {

// The number of (vertex, edge) pairs of the two operands, either operand's vertices
// against either operand's edges, where the vertex lies within the snap distance of the
// edge without lying on it.
inline std::size_t count_sub_resolution_pairs(const clipper::PolygonSet2& subject,
                                              const clipper::PolygonSet2& clip) {
  std::vector<const clipper::Loop2*> loops;
  for (const clipper::PolygonSet2* set : {&subject, &clip}) {
    for (const clipper::PolygonWithHoles2& p : *set) {
      loops.push_back(&p.outer);
      for (const clipper::Loop2& h : p.holes) loops.push_back(&h);
    }
  }
  std::size_t count = 0;
  for (const clipper::Loop2* edges : loops) {
    for (std::size_t i = 0; i < edges->size(); ++i) {
      const clipper::Point2& a = (*edges)[i];
      const clipper::Point2& b = (*edges)[(i + 1) % edges->size()];
      if (a == b) continue;
      for (const clipper::Loop2* vertices : loops) {
        for (const clipper::Point2& v : *vertices) {
          if (clipper::detail::within_snap_distance(v, a, b) &&
              clipper::orient2d(a, b, v) != clipper::Orientation::kCollinear) {
            ++count;
          }
        }
      }
    }
  }
  return count;
}

}  // namespace shadowgen::fuzz
