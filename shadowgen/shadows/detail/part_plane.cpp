#include "part_plane.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "clipper/clip.h"
#include "clipper/merge.h"
#include "hsr/plane_chart.h"

namespace shadowgen::shadows::detail {

std::vector<hsr::Polygon3> unite_views(std::span<const std::vector<hsr::Polygon3>> per_view,
                                       const hsr::Plane3& plane) {
  glm::dvec3 origin(0.0);
  for (const std::vector<hsr::Polygon3>& view : per_view) {
    if (!view.empty()) {
      origin = view.front().outer.front();
      break;
    }
  }
  hsr::ChartedPlane chart(plane.normal, origin, hsr::ChartFrom::kOrigin);
  clipper::PolygonSet2 united;
  for (const std::vector<hsr::Polygon3>& view : per_view) {
    clipper::PolygonSet2 seen;
    for (const hsr::Polygon3& p : view) seen.push_back(chart.flatten_known(p));
    if (seen.empty()) continue;
    // What this view adds: its pieces less what earlier views lit. Disjoint by
    // construction, with boundaries shared exactly, so the merge below joins them.
    clipper::PolygonSet2 added = united.empty() ? seen : clipper::difference(seen, united);
    for (clipper::PolygonWithHoles2& q : added) united.push_back(std::move(q));
  }
  return chart.lift(clipper::merge_adjacent(united));
}

std::vector<hsr::Polygon3> within_part(std::span<const hsr::Polygon3> lit,
                                       const hsr::Polygon3& part, const hsr::Plane3& plane) {
  hsr::ChartedPlane chart(plane.normal, part.outer.front(), hsr::ChartFrom::kOrigin);
  const clipper::PolygonWithHoles2 region = chart.flatten_known(part);
  clipper::PolygonSet2 flat;
  for (const hsr::Polygon3& p : lit) flat.push_back(chart.flatten_known(p));
  return chart.lift(clipper::intersection(flat, {region}));
}

namespace {

struct Box3 {
  glm::dvec3 lo{INFINITY};
  glm::dvec3 hi{-INFINITY};
};

Box3 box_of(const hsr::Loop3& loop) {
  Box3 box;
  for (const glm::dvec3& v : loop) {
    box.lo = glm::min(box.lo, v);
    box.hi = glm::max(box.hi, v);
  }
  return box;
}

double reach_of(const Box3& box) {
  const glm::dvec3 size = box.hi - box.lo;
  return 0x1p-40 *
         (std::max({size.x, size.y, size.z}) + std::max(glm::length(box.lo), glm::length(box.hi)));
}

}  // namespace

double part_reach(const hsr::Polygon3& part) { return reach_of(box_of(part.outer)); }

bool inside_box_of(std::span<const hsr::Polygon3> lit, const hsr::Polygon3& part) {
  const Box3 box = box_of(part.outer);
  // Points rounded onto the plane stay within the reach (they are a few ulps off);
  // points cast off a face seen edge-on do not.
  const double slack = reach_of(box);
  const glm::dvec3 lo = box.lo - slack;
  const glm::dvec3 hi = box.hi + slack;
  auto inside = [&](const hsr::Loop3& loop) {
    return std::all_of(loop.begin(), loop.end(), [&](const glm::dvec3& v) {
      return glm::all(glm::lessThanEqual(lo, v)) && glm::all(glm::lessThanEqual(v, hi));
    });
  };
  return std::all_of(lit.begin(), lit.end(), [&](const hsr::Polygon3& p) {
    return inside(p.outer) && std::all_of(p.holes.begin(), p.holes.end(), inside);
  });
}

}  // namespace shadowgen::shadows::detail
