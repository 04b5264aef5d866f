#include "chart_region.h"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "clipper/clip.h"
#include "clipper/placement.h"

namespace shadowgen::shadows::detail {
namespace {

bool overlaps_any(const clipper::Box2& box, const std::vector<clipper::Box2>& boxes) {
  return std::any_of(boxes.begin(), boxes.end(),
                     [&box](const clipper::Box2& b) { return b.overlaps(box); });
}

std::vector<clipper::Box2> boxes_of(const clipper::PolygonSet2& polygons) {
  std::vector<clipper::Box2> boxes;
  boxes.reserve(polygons.size());
  for (const clipper::PolygonWithHoles2& p : polygons) boxes.push_back(clipper::box_of(p));
  return boxes;
}

}  // namespace

ChartRegion::ChartRegion(const clipper::PolygonSet2& whole, clipper::PolygonSet2 inside)
    : inside_(std::move(inside)),
      inside_boxes_(boxes_of(inside_)),
      outside_boxes_(boxes_of(clipper::difference(whole, inside_))) {}

void ChartRegion::split(clipper::PolygonSet2 pieces, clipper::PolygonSet2& outside,
                        clipper::PolygonSet2& inside) const {
  // By boxes first: a piece whose box meets no polygon of one side lies in the other.
  clipper::PolygonSet2 undecided;
  std::vector<clipper::Box2> undecided_boxes;
  for (clipper::PolygonWithHoles2& piece : pieces) {
    const clipper::Box2 box = clipper::box_of(piece);
    if (!overlaps_any(box, inside_boxes_)) {
      outside.push_back(std::move(piece));
    } else if (!overlaps_any(box, outside_boxes_)) {
      inside.push_back(std::move(piece));
    } else {
      undecided.push_back(std::move(piece));
      undecided_boxes.push_back(box);
    }
  }
  if (undecided.empty()) return;

  // The region's polygons whose boxes meet theirs (closed boxes, as clip() takes
  // operands that touch: clipper/box.h).
  const auto near = [this](const std::vector<clipper::Box2>& boxes) {
    std::vector<const clipper::PolygonWithHoles2*> found;
    for (std::size_t k = 0; k < inside_.size(); ++k) {
      const clipper::Box2& b = inside_boxes_[k];
      if (std::any_of(boxes.begin(), boxes.end(),
                      [&b](const clipper::Box2& c) { return c.touches_or_overlaps(b); })) {
        found.push_back(&inside_[k]);
      }
    }
    return found;
  };
  const std::vector<const clipper::PolygonWithHoles2*> by = near(undecided_boxes);

  // A piece whose boundary the region's does not pass through lies wholly in it or
  // wholly out of it, decided exactly (clipper/placement.h); the others are clipped, all
  // in one clip.
  clipper::PolygonSet2 crossing;
  std::vector<clipper::Box2> crossing_boxes;
  for (std::size_t i = 0; i < undecided.size(); ++i) {
    switch (clipper::placement(undecided[i], by)) {
      case clipper::Placement::kInside:
        inside.push_back(std::move(undecided[i]));
        break;
      case clipper::Placement::kOutside:
        outside.push_back(std::move(undecided[i]));
        break;
      case clipper::Placement::kMeeting:
        crossing.push_back(std::move(undecided[i]));
        crossing_boxes.push_back(undecided_boxes[i]);
        break;
    }
  }
  if (crossing.empty()) return;
  clipper::PolygonSet2 clips;
  for (const clipper::PolygonWithHoles2* p : near(crossing_boxes)) clips.push_back(*p);
  clipper::ClipResult r = clipper::clip(crossing, clips);
  for (auto& p : r.inside) inside.push_back(std::move(p));
  for (auto& p : r.outside) outside.push_back(std::move(p));
}

}  // namespace shadowgen::shadows::detail
