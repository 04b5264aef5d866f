#include "hsr/plane_chart.h"

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>

#include "hsr/area.h"

namespace shadowgen::hsr {

clipper::Loop2 PlaneChart::flatten(const Loop3& loop) const {
  clipper::Loop2 out;
  out.reserve(loop.size());
  for (const glm::dvec3& p : loop) out.push_back((*this)(p));
  return out;
}

clipper::PolygonWithHoles2 PlaneChart::flatten(const Polygon3& polygon) const {
  clipper::PolygonWithHoles2 out{flatten(polygon.outer), {}};
  for (const Loop3& h : polygon.holes) out.holes.push_back(flatten(h));
  return out;
}

PlaneChart chart_facing(const glm::dvec3& normal) {
  const double ax = std::abs(normal.x);
  const double ay = std::abs(normal.y);
  const double az = std::abs(normal.z);
  if (az >= ax && az >= ay) return {2};
  return {ay >= ax ? 1 : 0};
}

ChartedPlane::ChartedPlane(const glm::dvec3& normal, const glm::dvec3& origin, ChartFrom from)
    : chart_(chart_facing(normal)),
      normal_(normal),
      origin_(origin),
      from_(from),
      origin_in_chart_(from == ChartFrom::kWorld ? chart_(origin) : clipper::Point2{}) {}

clipper::Point2 ChartedPlane::flatten(const glm::dvec3& p) const {
  return from_ == ChartFrom::kWorld ? chart_(p) : chart_(p - origin_);
}

clipper::Loop2 ChartedPlane::flatten(const Loop3& loop) const {
  clipper::Loop2 out;
  out.reserve(loop.size());
  for (const glm::dvec3& p : loop) out.push_back(flatten(p));
  return out;
}

clipper::PolygonWithHoles2 ChartedPlane::flatten(const Polygon3& polygon) const {
  clipper::PolygonWithHoles2 out{flatten(polygon.outer), {}};
  for (const Loop3& h : polygon.holes) out.holes.push_back(flatten(h));
  return out;
}

clipper::Loop2 ChartedPlane::flatten_known(const Loop3& loop) {
  clipper::Loop2 out;
  out.reserve(loop.size());
  for (const glm::dvec3& p : loop) {
    const clipper::Point2 q = flatten(p);
    known_.emplace(q, p);
    out.push_back(q);
  }
  return out;
}

clipper::PolygonWithHoles2 ChartedPlane::flatten_known(const Polygon3& polygon) {
  clipper::PolygonWithHoles2 out{flatten_known(polygon.outer), {}};
  for (const Loop3& h : polygon.holes) out.holes.push_back(flatten_known(h));
  return out;
}

glm::dvec3 ChartedPlane::lift(const clipper::Point2& q) const {
  const auto it = known_.find(q);
  return it != known_.end() ? it->second : on_plane(q);
}

glm::dvec3 ChartedPlane::on_plane(const clipper::Point2& q) const {
  const int d = chart_.dropped_axis, i = chart_.first_kept(), j = chart_.second_kept();
  const glm::dvec3& n = normal_;
  // Along the plane from the origin: n · (p − origin) = 0, solved for the dropped
  // coordinate, which the normal's largest component makes the best conditioned.
  const double along =
      -(n[i] * (q.x - origin_in_chart_.x) + n[j] * (q.y - origin_in_chart_.y)) / n[d];
  glm::dvec3 p;
  p[d] = origin_[d] + along;
  if (from_ == ChartFrom::kWorld) {
    p[i] = q.x;
    p[j] = q.y;
  } else {
    p[i] = origin_[i] + q.x;
    p[j] = origin_[j] + q.y;
  }
  return p;
}

Loop3 ChartedPlane::lift(const clipper::Loop2& loop) const {
  Loop3 out;
  out.reserve(loop.size());
  for (const clipper::Point2& q : loop) out.push_back(lift(q));
  if (mirrors()) std::reverse(out.begin(), out.end());
  return out;
}

Polygon3 ChartedPlane::lift(const clipper::PolygonWithHoles2& polygon) const {
  Polygon3 out{lift(polygon.outer), {}};
  for (const clipper::Loop2& h : polygon.holes) out.holes.push_back(lift(h));
  return out;
}

std::vector<Polygon3> ChartedPlane::lift(const clipper::PolygonSet2& set) const {
  std::vector<Polygon3> out;
  out.reserve(set.size());
  for (const clipper::PolygonWithHoles2& q : set) out.push_back(lift(q));
  return out;
}

ChartAffine ChartedPlane::dot_on_plane(const glm::dvec3& g) const {
  const int d = chart_.dropped_axis, i = chart_.first_kept(), j = chart_.second_kept();
  const glm::dvec3& n = normal_;
  ChartAffine f;
  f.a = g[i] - g[d] * n[i] / n[d];
  f.b = g[j] - g[d] * n[j] / n[d];
  // At the chart's origin point, g · (the point there).
  if (from_ == ChartFrom::kWorld) {
    f.c = g[d] * (n[i] * origin_[i] + n[j] * origin_[j] + n[d] * origin_[d]) / n[d];
  } else {
    f.c = g[0] * origin_[0] + g[1] * origin_[1] + g[2] * origin_[2];
  }
  return f;
}

std::optional<OwnChart> own_chart(const Polygon3& polygon) {
  const Plane3 plane = plane_of(polygon);
  if (plane.normal == glm::dvec3(0.0) || !(area(polygon) > 0.0)) return std::nullopt;
  OwnChart own{ChartedPlane(plane.normal, polygon.outer[0], ChartFrom::kWorld), {}};
  own.flat = own.chart.flatten_known(polygon);
  return own;
}

}  // namespace shadowgen::hsr
