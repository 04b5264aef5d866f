#pragma once

// Well-formedness of polygon sets, decided exactly with clipper/predicates.h: the
// contract clip.h sets for its inputs, and what its outputs must satisfy. Written from
// that contract alone, all pairs against all pairs (O(n²) in the vertices), so that it
// shares nothing with the clipper's sweep.
//
// A set is well formed when
//   - every loop, once repeated consecutive vertices are dropped, is strictly simple: at
//     least three vertices, non-adjacent edges disjoint, adjacent edges meeting only at
//     their shared vertex (no spike; collinear vertices are allowed);
//   - two different loops meet at most at isolated points: no proper crossing, no
//     collinear overlap of positive length, and no crossing at a touching point either
//     (each boundary lies wholly on one side of the other);
//   - each hole lies inside its outer loop, the holes of a polygon lie outside each
//     other, and two polygons are interior-disjoint (one may sit in a hole of the other).

#include <algorithm>
#include <cstddef>
#include <vector>

#include "clipper/polygon.h"
#include "clipper/predicates.h"

namespace shadowgen::fuzz {

using clipper::Loop2;
using clipper::Orientation;
using clipper::Point2;
using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

inline int sign_of(Orientation o) { return static_cast<int>(o); }

// The loop without repeated consecutive vertices (the closing pair included).
inline Loop2 without_repeats(const Loop2& loop) {
  Loop2 out;
  for (const Point2& p : loop) {
    if (out.empty() || !(out.back() == p)) out.push_back(p);
  }
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

// The closed segments [a, b] and [c, d] share at least one point.
inline bool segments_meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Orientation o1 = clipper::orient2d(a, b, c);
  const Orientation o2 = clipper::orient2d(a, b, d);
  const Orientation o3 = clipper::orient2d(c, d, a);
  const Orientation o4 = clipper::orient2d(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return clipper::on_segment(a, b, c) || clipper::on_segment(a, b, d) ||
         clipper::on_segment(c, d, a) || clipper::on_segment(c, d, b);
}

// Strictly simple, for a loop without repeated consecutive vertices.
inline bool is_simple_loop(const Loop2& loop) {
  const std::size_t n = loop.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Point2& c = loop[j];
      const Point2& d = loop[(j + 1) % n];
      if (j == i + 1) {
        // Edges a-b and b-d: nothing but b in common, so d is not on a-b, a not on b-d.
        if (clipper::on_segment(a, b, d) || clipper::on_segment(c, d, a)) return false;
      } else if (i == 0 && j == n - 1) {
        // Edges a-b and c-a, the closing edge.
        if (clipper::on_segment(a, b, c) || clipper::on_segment(c, d, b)) return false;
      } else if (segments_meet(a, b, c, d)) {
        return false;
      }
    }
  }
  return true;
}

// Edges of two different loops meet at most at single points: no proper crossing, no
// collinear overlap of positive length. (A crossing at a touching point is caught by
// side_of.)
inline bool meet_at_points_only(const Loop2& a, const Loop2& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Point2& p = a[i];
    const Point2& q = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Point2& r = b[j];
      const Point2& s = b[(j + 1) % b.size()];
      const int o1 = sign_of(clipper::orient2d(p, q, r));
      const int o2 = sign_of(clipper::orient2d(p, q, s));
      const int o3 = sign_of(clipper::orient2d(r, s, p));
      const int o4 = sign_of(clipper::orient2d(r, s, q));
      if (o1 * o2 < 0 && o3 * o4 < 0) return false;
      if (o1 == 0 && o2 == 0) {
        // On one line the lexicographic order is the order along the line.
        const Point2 low = std::max(std::min(p, q), std::min(r, s));
        const Point2 high = std::min(std::max(p, q), std::max(r, s));
        if (low < high) return false;
      }
    }
  }
  return true;
}

enum class Location { kInside, kOutside, kBoundary };

// Exact point location: boundary test, then the crossing number of the ray towards +x
// (half-open in y, so a vertex at the ray's height is counted once).
inline Location locate(const Point2& p, const Loop2& loop) {
  bool inside = false;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[(i + 1) % loop.size()];
    if (clipper::on_segment(a, b, p)) return Location::kBoundary;
    if ((a.y > p.y) != (b.y > p.y)) {
      const bool upward = b.y > a.y;
      const bool left = clipper::orient2d(a, b, p) == Orientation::kCounterClockwise;
      if (upward == left) inside = !inside;
    }
  }
  return inside ? Location::kInside : Location::kOutside;
}

// kUndecided: a sample point between two touching points could not be formed exactly
// (the input is then skipped, not judged).
enum class Side { kInside, kOutside, kCrossing, kUndecided };

// Where the boundary `a` lies with respect to the region of loop `b`, the two loops
// meeting at points only (meet_at_points_only). The touching points cut `a` into arcs,
// each wholly inside or wholly outside `b`; every arc is sampled, at a vertex of `a` off
// `b` where it has one, else at the exact midpoint of its single piece of edge.
inline Side side_of(const Loop2& a, const Loop2& b) {
  bool seen_inside = false;
  bool seen_outside = false;
  std::vector<bool> on_b(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Location where = locate(a[i], b);
    on_b[i] = where == Location::kBoundary;
    if (where == Location::kInside) seen_inside = true;
    if (where == Location::kOutside) seen_outside = true;
  }
  std::vector<Point2> stops;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t next = (i + 1) % a.size();
    stops.assign({a[i], a[next]});
    for (const Point2& v : b) {
      if (clipper::on_segment(a[i], a[next], v)) stops.push_back(v);
    }
    std::sort(stops.begin(), stops.end());
    stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
    for (std::size_t k = 0; k + 1 < stops.size(); ++k) {
      const Point2& s = stops[k];
      const Point2& t = stops[k + 1];
      // A stop inside the edge is a vertex of `b`, so a touching point; an end of the
      // edge touches when it lies on `b`. Past a stop that does not touch, the arc goes on
      // to a vertex of `a` off `b`, sampled above.
      const bool s_touches = !(s == a[i] || s == a[next]) || on_b[s == a[i] ? i : next];
      const bool t_touches = !(t == a[i] || t == a[next]) || on_b[t == a[i] ? i : next];
      if (!s_touches || !t_touches) continue;
      const Point2 m{0.5 * s.x + 0.5 * t.x, 0.5 * s.y + 0.5 * t.y};
      if (!(s < m && m < t) || clipper::orient2d(a[i], a[next], m) != Orientation::kCollinear) {
        return Side::kUndecided;
      }
      switch (locate(m, b)) {
        case Location::kInside:
          seen_inside = true;
          break;
        case Location::kOutside:
          seen_outside = true;
          break;
        case Location::kBoundary:
          return Side::kUndecided;
      }
    }
  }
  if (seen_inside && seen_outside) return Side::kCrossing;
  return seen_inside ? Side::kInside : Side::kOutside;
}

// The well-formedness described at the top, for a set as given (repeated consecutive
// vertices allowed; the caller checks their absence where it matters).
inline bool is_well_formed(const PolygonSet2& polygons) {
  PolygonSet2 clean;
  std::vector<const Loop2*> loops;
  clean.reserve(polygons.size());
  for (const PolygonWithHoles2& polygon : polygons) {
    PolygonWithHoles2& c = clean.emplace_back();
    c.outer = without_repeats(polygon.outer);
    if (!is_simple_loop(c.outer)) return false;
    for (const Loop2& hole : polygon.holes) {
      c.holes.push_back(without_repeats(hole));
      if (!is_simple_loop(c.holes.back())) return false;
    }
  }
  for (const PolygonWithHoles2& polygon : clean) {
    loops.push_back(&polygon.outer);
    for (const Loop2& hole : polygon.holes) loops.push_back(&hole);
  }
  for (std::size_t i = 0; i < loops.size(); ++i) {
    for (std::size_t j = i + 1; j < loops.size(); ++j) {
      if (!meet_at_points_only(*loops[i], *loops[j])) return false;
    }
  }
  for (const PolygonWithHoles2& polygon : clean) {
    for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
      if (side_of(polygon.holes[h], polygon.outer) != Side::kInside) return false;
      for (std::size_t g = h + 1; g < polygon.holes.size(); ++g) {
        if (side_of(polygon.holes[h], polygon.holes[g]) != Side::kOutside ||
            side_of(polygon.holes[g], polygon.holes[h]) != Side::kOutside) {
          return false;
        }
      }
    }
  }
  // Two polygons: side by side, or one inside a hole of the other.
  auto inside_a_hole = [](const Loop2& outer, const PolygonWithHoles2& host) {
    return std::any_of(host.holes.begin(), host.holes.end(),
                       [&](const Loop2& hole) { return side_of(outer, hole) == Side::kInside; });
  };
  for (std::size_t i = 0; i < clean.size(); ++i) {
    for (std::size_t j = i + 1; j < clean.size(); ++j) {
      const Side i_in_j = side_of(clean[i].outer, clean[j].outer);
      const Side j_in_i = side_of(clean[j].outer, clean[i].outer);
      if (i_in_j == Side::kOutside && j_in_i == Side::kOutside) continue;
      if (i_in_j == Side::kInside && inside_a_hole(clean[i].outer, clean[j])) continue;
      if (j_in_i == Side::kInside && inside_a_hole(clean[j].outer, clean[i])) continue;
      return false;
    }
  }
  return true;
}

}  // namespace shadowgen::fuzz
