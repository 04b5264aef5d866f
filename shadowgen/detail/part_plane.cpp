#include "shadowgen/detail/part_plane.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <unordered_map>

#include "clipper/clip.h"
#include "clipper/merge.h"
#include "shadowgen/detail/plane_chart.h"

namespace shadowgen::detail {
namespace {

// Chart coordinates relative to `origin`, a vertex on the plane: far from the origin of
// the scene (1e8) the offsets of nearby points are exact and small, so clipping in the
// chart keeps their precision. Back to 3D: the vertices that came in by lookup (exact),
// others by the plane's equation n·d = 0 (it passes through the origin vertex) solved for
// the dropped coordinate, the best-conditioned one (the normal's largest component).
class Lifter {
 public:
  Lifter(const PlaneChart& chart, const hsr::Plane3& plane, const glm::dvec3& origin)
      : chart_(chart), plane_(plane), origin_(origin) {}

  clipper::Loop2 flatten(const hsr::Loop3& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) {
      const clipper::Point2 q = chart_(p - origin_);
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
      out.push_back(it != known_.end() ? it->second : origin_ + on_plane(q));
    }
    return out;
  }

 private:
  glm::dvec3 on_plane(const clipper::Point2& q) const {
    const glm::dvec3& n = plane_.normal;
    switch (chart_.dropped_axis) {
      case 0:  // (y, z) kept
        return {-(n.y * q.x + n.z * q.y) / n.x, q.x, q.y};
      case 1:  // (z, x) kept
        return {q.y, -(n.z * q.x + n.x * q.y) / n.y, q.x};
      default:  // (x, y) kept
        return {q.x, q.y, -(n.x * q.x + n.y * q.y) / n.z};
    }
  }

  PlaneChart chart_;
  hsr::Plane3 plane_;
  glm::dvec3 origin_;
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> known_;
};

clipper::PolygonWithHoles2 flatten(Lifter& lifter, const hsr::Polygon3& p) {
  clipper::PolygonWithHoles2 q{lifter.flatten(p.outer), {}};
  for (const hsr::Loop3& h : p.holes) q.holes.push_back(lifter.flatten(h));
  return q;
}

// Back to 3D, outer loops counter-clockwise seen from the side the normal points to (the
// chart keeps orientation only where the dropped normal component is positive).
std::vector<hsr::Polygon3> lift_all(const Lifter& lifter, const clipper::PolygonSet2& set,
                                    const PlaneChart& chart, const hsr::Plane3& plane) {
  const double dropped = plane.normal[chart.dropped_axis];
  std::vector<hsr::Polygon3> out;
  for (const clipper::PolygonWithHoles2& q : set) {
    hsr::Polygon3 p{lifter.lift(q.outer), {}};
    for (const clipper::Loop2& h : q.holes) p.holes.push_back(lifter.lift(h));
    if (dropped < 0.0) {
      std::reverse(p.outer.begin(), p.outer.end());
      for (hsr::Loop3& h : p.holes) std::reverse(h.begin(), h.end());
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

std::vector<hsr::Polygon3> unite_views(std::span<const std::vector<hsr::Polygon3>> per_view,
                                       const hsr::Plane3& plane) {
  const PlaneChart chart = chart_facing(plane.normal);
  glm::dvec3 origin(0.0);
  for (const std::vector<hsr::Polygon3>& view : per_view) {
    if (!view.empty()) {
      origin = view.front().outer.front();
      break;
    }
  }
  Lifter lifter(chart, plane, origin);
  clipper::PolygonSet2 united;
  for (const std::vector<hsr::Polygon3>& view : per_view) {
    clipper::PolygonSet2 seen;
    for (const hsr::Polygon3& p : view) seen.push_back(flatten(lifter, p));
    if (seen.empty()) continue;
    // What this view adds: its pieces less what earlier views lit. Disjoint by
    // construction, with boundaries shared exactly, so the merge below joins them.
    clipper::PolygonSet2 added = united.empty() ? seen : clipper::difference(seen, united);
    for (clipper::PolygonWithHoles2& q : added) united.push_back(std::move(q));
  }
  return lift_all(lifter, clipper::merge_adjacent(united), chart, plane);
}

std::vector<hsr::Polygon3> within_part(std::span<const hsr::Polygon3> lit,
                                       const hsr::Polygon3& part, const hsr::Plane3& plane) {
  const PlaneChart chart = chart_facing(plane.normal);
  Lifter lifter(chart, plane, part.outer.front());
  const clipper::PolygonWithHoles2 region = flatten(lifter, part);
  clipper::PolygonSet2 flat;
  for (const hsr::Polygon3& p : lit) flat.push_back(flatten(lifter, p));
  return lift_all(lifter, clipper::intersection(flat, {region}), chart, plane);
}

bool inside_box_of(std::span<const hsr::Polygon3> lit, const hsr::Polygon3& part) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec3& v : part.outer) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  // Grown by 2^-40 of the box's size and position: points rounded onto the plane stay
  // within that (they are a few ulps off); points cast off a face seen edge-on do not.
  const glm::dvec3 size = hi - lo;
  const double slack =
      0x1p-40 * (std::max({size.x, size.y, size.z}) + std::max(glm::length(lo), glm::length(hi)));
  lo -= slack;
  hi += slack;
  auto inside = [&](const hsr::Loop3& loop) {
    return std::all_of(loop.begin(), loop.end(), [&](const glm::dvec3& v) {
      return glm::all(glm::lessThanEqual(lo, v)) && glm::all(glm::lessThanEqual(v, hi));
    });
  };
  return std::all_of(lit.begin(), lit.end(), [&](const hsr::Polygon3& p) {
    return inside(p.outer) && std::all_of(p.holes.begin(), p.holes.end(), inside);
  });
}

}  // namespace shadowgen::detail
