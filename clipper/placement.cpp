#include "clipper/placement.h"

#include <algorithm>
#include <vector>

#include "clipper/box.h"
#include "clipper/predicates.h"
#include "clipper/segment_contact.h"
#include "detail/point_location.h"

namespace shadowgen::clipper {
namespace {

template <class Visit>
bool any_loop(const PolygonWithHoles2& p, Visit&& visit) {
  if (visit(p.outer)) return true;
  for (const Loop2& hole : p.holes) {
    if (!hole.empty() && visit(hole)) return true;
  }
  return false;
}

// Winding number of `p` about the loops of `polygon`, added to `winding`; false when p
// lies on one of them.
template <class P>
bool add_winding(const P& p, const PolygonWithHoles2& polygon, int& winding) {
  return !any_loop(polygon, [&p, &winding](const Loop2& loop) {
    return !detail::add_winding_number(p, loop, winding);
  });
}

// Inside for either orientation of the outer loop (holes run against it).
bool strictly_inside(const Midpoint2& m, const PolygonWithHoles2& polygon) {
  int winding = 0;
  return add_winding(m, polygon, winding) && winding != 0;
}

// The points where the segment [b0, b1] meets the boundary of `other`, with b0 and b1,
// in order along it and without repeats; false when it crosses an edge of `other`
// properly. Touches and overlaps meet at vertices of either (clipper/segment_contact.h),
// so between consecutive points the open segment lies wholly inside `other`, outside it
// or on its boundary, as the exact midpoint tells.
bool stops_along(const Point2& b0, const Point2& b1, const PolygonWithHoles2& other,
                 std::vector<Point2>& stops) {
  const Box2 edge = box_of(b0, b1);
  stops.assign({b0, b1});
  const bool crossed = any_loop(other, [&](const Loop2& loop) {
    if (!edge.touches_or_overlaps(box_of(loop))) return false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& a0 = loop[i];
      const Point2& a1 = loop[(i + 1) % loop.size()];
      if (a0 == a1 || !edge.touches_or_overlaps(box_of(a0, a1))) continue;
      const SegmentContact c = segment_contact(a0, a1, b0, b1);
      switch (c.contact) {
        case Contact::kNone:
          break;
        case Contact::kCross:
          return true;
        case Contact::kTouch:
          stops.push_back(c.at);
          break;
        case Contact::kOverlap:
          if (on_segment(b0, b1, a0)) stops.push_back(a0);
          if (on_segment(b0, b1, a1)) stops.push_back(a1);
          break;
      }
    }
    return false;
  });
  if (crossed) return false;
  // Points of one segment in lexicographic order are in order along it.
  std::sort(stops.begin(), stops.end(), [](const Point2& p, const Point2& q) {
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
  return true;
}

// Calls visit(a, b) for every edge of positive length of `polygon`'s loops whose box
// meets `box`, until it returns true; returns whether it did.
template <class Visit>
bool any_edge(const PolygonWithHoles2& polygon, const Box2& box, Visit&& visit) {
  return any_loop(polygon, [&](const Loop2& loop) {
    if (!box.touches_or_overlaps(box_of(loop))) return false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& a = loop[i];
      const Point2& b = loop[(i + 1) % loop.size()];
      if (a != b && box.touches_or_overlaps(box_of(a, b)) && visit(a, b)) return true;
    }
    return false;
  });
}

}  // namespace

Placement placement(const PolygonWithHoles2& polygon,
                    std::span<const PolygonWithHoles2* const> region) {
  if (polygon.outer.empty()) return Placement::kOutside;
  const Box2 box = box_of(polygon);
  std::vector<const PolygonWithHoles2*> near;
  std::vector<Point2> stops;
  for (const PolygonWithHoles2* r : region) {
    if (r->outer.empty() || !box.touches_or_overlaps(box_of(*r))) continue;
    near.push_back(r);
    // Does the region's boundary pass through the polygon's interior?
    const bool enters = any_edge(*r, box, [&](const Point2& b0, const Point2& b1) {
      if (!stops_along(b0, b1, polygon, stops)) return true;
      for (std::size_t i = 0; i + 1 < stops.size(); ++i) {
        if (strictly_inside(Midpoint2{stops[i], stops[i + 1]}, polygon)) return true;
      }
      return false;
    });
    if (enters) return Placement::kMeeting;
  }
  // It does not: each connected piece of the interior lies wholly inside the region or
  // wholly outside, as any point of the polygon's boundary off the region's boundary
  // tells (the region is the same on both sides of the boundary there). The boundary is
  // cut where it meets the region's, and every stretch asked, so that the interiors of
  // several pieces must agree.
  bool seen = false, in = false;
  const bool disagree = any_edge(polygon, box, [&](const Point2& a0, const Point2& a1) {
    stops.assign({a0, a1});
    std::vector<Point2> all;
    for (const PolygonWithHoles2* r : near) {
      stops_along(a0, a1, *r, all);  // no crossing: the pass above found none
      stops.insert(stops.end(), all.begin(), all.end());
    }
    std::sort(stops.begin(), stops.end(), [](const Point2& p, const Point2& q) {
      return p.x < q.x || (p.x == q.x && p.y < q.y);
    });
    stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
    for (std::size_t i = 0; i + 1 < stops.size(); ++i) {
      const Midpoint2 m{stops[i], stops[i + 1]};
      bool off = true, inside_some = false;
      for (const PolygonWithHoles2* r : near) {
        int winding = 0;
        off = add_winding(m, *r, winding);
        if (!off) break;
        inside_some = inside_some || winding != 0;
      }
      if (!off) continue;
      if (seen && in != inside_some) return true;
      seen = true;
      in = inside_some;
    }
    return false;
  });
  if (disagree || !seen) return Placement::kMeeting;
  return in ? Placement::kInside : Placement::kOutside;
}

}  // namespace shadowgen::clipper
