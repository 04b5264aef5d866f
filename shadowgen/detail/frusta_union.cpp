#include "shadowgen/detail/frusta_union.h"

#include <algorithm>
#include <unordered_map>

#include "clipper/clip.h"
#include "clipper/merge.h"
#include "shadowgen/detail/plane_chart.h"

namespace shadowgen::detail {
namespace {

// Chart points back to 3D: the vertices that came in by lookup (exact), others by the
// plane's equation solved for the dropped coordinate, the best-conditioned one (the
// normal's largest component).
class Lifter {
 public:
  Lifter(const PlaneChart& chart, const hsr::Plane3& plane) : chart_(chart), plane_(plane) {}

  clipper::Loop2 flatten(const hsr::Loop3& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) {
      const clipper::Point2 q = chart_(p);
      known_.emplace(q, p);
      out.push_back(q);
    }
    return out;
  }

  hsr::Loop3 lift(const clipper::Loop2& loop) const {
    hsr::Loop3 out;
    out.reserve(loop.size());
    for (const clipper::Point2& q : loop) {
      const auto it = known_.find(q);
      out.push_back(it != known_.end() ? it->second : on_plane(q));
    }
    return out;
  }

 private:
  glm::dvec3 on_plane(const clipper::Point2& q) const {
    const glm::dvec3& n = plane_.normal;
    switch (chart_.dropped_axis) {
      case 0:  // (y, z) kept
        return {(plane_.offset - n.y * q.x - n.z * q.y) / n.x, q.x, q.y};
      case 1:  // (z, x) kept
        return {q.y, (plane_.offset - n.z * q.x - n.x * q.y) / n.y, q.x};
      default:  // (x, y) kept
        return {q.x, q.y, (plane_.offset - n.x * q.x - n.y * q.y) / n.z};
    }
  }

  PlaneChart chart_;
  hsr::Plane3 plane_;
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> known_;
};

}  // namespace

std::vector<hsr::Polygon3> unite_views(std::span<const std::vector<hsr::Polygon3>> per_view,
                                       const hsr::Plane3& plane) {
  const PlaneChart chart = chart_facing(plane.normal);
  Lifter lifter(chart, plane);
  clipper::PolygonSet2 united;
  for (const std::vector<hsr::Polygon3>& view : per_view) {
    clipper::PolygonSet2 seen;
    for (const hsr::Polygon3& p : view) {
      clipper::PolygonWithHoles2 q{lifter.flatten(p.outer), {}};
      for (const hsr::Loop3& h : p.holes) q.holes.push_back(lifter.flatten(h));
      seen.push_back(std::move(q));
    }
    if (seen.empty()) continue;
    // What this view adds: its pieces less what earlier views lit. Disjoint by
    // construction, with boundaries shared exactly, so the merge below joins them.
    clipper::PolygonSet2 added = united.empty() ? seen : clipper::difference(seen, united);
    for (clipper::PolygonWithHoles2& q : added) united.push_back(std::move(q));
  }
  const double dropped = chart.dropped_axis == 0   ? plane.normal.x
                         : chart.dropped_axis == 1 ? plane.normal.y
                                                   : plane.normal.z;
  std::vector<hsr::Polygon3> out;
  for (const clipper::PolygonWithHoles2& q : clipper::merge_adjacent(united)) {
    hsr::Polygon3 p{lifter.lift(q.outer), {}};
    for (const clipper::Loop2& h : q.holes) p.holes.push_back(lifter.lift(h));
    // The chart keeps orientation only where the dropped normal component is positive.
    if (dropped < 0.0) {
      std::reverse(p.outer.begin(), p.outer.end());
      for (hsr::Loop3& h : p.holes) std::reverse(h.begin(), h.end());
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace shadowgen::detail
