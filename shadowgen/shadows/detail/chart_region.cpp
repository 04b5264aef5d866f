#include "chart_region.h"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "clipper/clip.h"
#include "clipper/placement.h"

namespace shadowgen::detail {
namespace {

bool overlaps_any(const clipper::Box2& box, const std::vector<clipper::Box2>& boxes) {
  return std::any_of(boxes.begin(), boxes.end(),
                     [&box](const clipper::Box2& b) { return b.overlaps(box); });
}

}  // namespace

ChartRegion::Side ChartRegion::side_of(clipper::PolygonSet2 polygons) {
  Side side{std::move(polygons), {}};
  side.boxes.reserve(side.polygons.size());
  for (const clipper::PolygonWithHoles2& p : side.polygons)
    side.boxes.push_back(clipper::box_of(p));
  return side;
}

ChartRegion::ChartRegion(const clipper::PolygonSet2& whole, clipper::PolygonSet2 inside)
    : inside_(side_of(std::move(inside))),
      outside_(side_of(clipper::difference(whole, inside_.polygons))) {}

void ChartRegion::split(clipper::PolygonSet2 pieces, clipper::PolygonSet2& outside,
                        clipper::PolygonSet2& inside) const {
  // By boxes first: a piece whose box meets no polygon of one side lies in the other.
  clipper::PolygonSet2 near_edges;
  std::vector<clipper::Box2> near_boxes;
  for (clipper::PolygonWithHoles2& piece : pieces) {
    const clipper::Box2 box = clipper::box_of(piece);
    if (!overlaps_any(box, inside_.boxes)) {
      outside.push_back(std::move(piece));
    } else if (!overlaps_any(box, outside_.boxes)) {
      inside.push_back(std::move(piece));
    } else {
      near_edges.push_back(std::move(piece));
      near_boxes.push_back(box);
    }
  }
  if (near_edges.empty()) return;

  // The rest against one side, the region's polygons or the complement's, whichever has
  // fewer vertices among those whose boxes meet theirs (closed boxes, as clip() takes
  // operands that touch: clipper/box.h).
  const auto near = [](const Side& side, const std::vector<clipper::Box2>& boxes,
                       std::size_t& vertices) {
    std::vector<const clipper::PolygonWithHoles2*> found;
    vertices = 0;
    for (std::size_t k = 0; k < side.polygons.size(); ++k) {
      const clipper::Box2& b = side.boxes[k];
      if (std::any_of(boxes.begin(), boxes.end(),
                      [&b](const clipper::Box2& c) { return c.touches_or_overlaps(b); })) {
        found.push_back(&side.polygons[k]);
        vertices += clipper::vertex_count(side.polygons[k]);
      }
    }
    return found;
  };
  std::size_t inside_vertices = 0, outside_vertices = 0;
  std::vector<const clipper::PolygonWithHoles2*> by = near(inside_, near_boxes, inside_vertices);
  std::vector<const clipper::PolygonWithHoles2*> near_outside =
      near(outside_, near_boxes, outside_vertices);
  const bool by_complement = outside_vertices < inside_vertices;
  if (by_complement) by = std::move(near_outside);
  clipper::PolygonSet2& in_by = by_complement ? outside : inside;
  clipper::PolygonSet2& out_by = by_complement ? inside : outside;

  // A piece whose boundary meets none of that side's lies wholly in it or wholly out of
  // it, decided exactly (clipper/placement.h); the others are clipped, all in one clip.
  clipper::PolygonSet2 crossing;
  std::vector<clipper::Box2> crossing_boxes;
  for (std::size_t i = 0; i < near_edges.size(); ++i) {
    switch (clipper::placement(near_edges[i], by)) {
      case clipper::Placement::kInside:
        in_by.push_back(std::move(near_edges[i]));
        break;
      case clipper::Placement::kOutside:
        out_by.push_back(std::move(near_edges[i]));
        break;
      case clipper::Placement::kMeeting:
        crossing.push_back(std::move(near_edges[i]));
        crossing_boxes.push_back(near_boxes[i]);
        break;
    }
  }
  if (crossing.empty()) return;
  clipper::PolygonSet2 clips;
  std::size_t unused = 0;
  for (const clipper::PolygonWithHoles2* p :
       near(by_complement ? outside_ : inside_, crossing_boxes, unused)) {
    clips.push_back(*p);
  }
  clipper::ClipResult r = clipper::clip(crossing, clips);
  for (auto& p : r.inside) in_by.push_back(std::move(p));
  for (auto& p : r.outside) out_by.push_back(std::move(p));
}

}  // namespace shadowgen::detail
