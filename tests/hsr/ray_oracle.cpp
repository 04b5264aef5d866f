#include "tests/hsr/ray_oracle.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace shadowgen::test {
namespace {

using clipper::Point2;

double segment_distance(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// Crossing rule over all loops (outer and holes alike): inside when an odd number of
// edges cross the horizontal ray to the right of p. Only trusted away from the boundary.
bool crosses_odd(const std::vector<clipper::Loop2>& loops, const Point2& p) {
  bool inside = false;
  for (const clipper::Loop2& loop : loops) {
    const std::size_t n = loop.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const Point2& a = loop[i];
      const Point2& b = loop[j];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
        inside = !inside;
      }
    }
  }
  return inside;
}

}  // namespace

RayOracle::RayOracle(std::span<const hsr::Polygon3> polygons, const hsr::View& view,
                     RayTolerance tolerance)
    : view_(view), tolerance_(tolerance), origin_(view.eye()) {
  faces_.reserve(polygons.size());
  for (const hsr::Polygon3& polygon : polygons) {
    Face face;
    const hsr::Loop3& outer = polygon.outer;
    if (outer.size() >= 3) {
      const glm::dvec3 first = outer[0] - origin_;
      glm::dvec3 normal(0.0), centroid(0.0);
      for (std::size_t i = 0; i < outer.size(); ++i) {
        const glm::dvec3 a = (outer[i] - origin_) - first;
        const glm::dvec3 b = (outer[(i + 1) % outer.size()] - origin_) - first;
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                             (a.x - b.x) * (a.y + b.y));
        centroid += a;
      }
      const double length = glm::length(normal);
      if (length > 0.0) {
        face.usable = true;
        face.normal = normal / length;
        face.point = first + centroid / static_cast<double>(outer.size());
        const glm::dvec3 a = glm::abs(face.normal);
        face.drop = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        face.xmin = face.ymin = std::numeric_limits<double>::infinity();
        face.xmax = face.ymax = -std::numeric_limits<double>::infinity();
        auto add_loop = [&](const hsr::Loop3& loop) {
          clipper::Loop2 chart;
          for (const glm::dvec3& p : loop) {
            chart.push_back(to_chart(face, p - origin_));
            face.xmin = std::min(face.xmin, chart.back().x);
            face.xmax = std::max(face.xmax, chart.back().x);
            face.ymin = std::min(face.ymin, chart.back().y);
            face.ymax = std::max(face.ymax, chart.back().y);
          }
          face.chart_loops.push_back(std::move(chart));
        };
        add_loop(outer);
        for (const hsr::Loop3& hole : polygon.holes) add_loop(hole);
      }
    }
    faces_.push_back(std::move(face));
  }
}

Point2 RayOracle::to_chart(const Face& face, const glm::dvec3& p) const {
  return {p[(face.drop + 1) % 3], p[(face.drop + 2) % 3]};
}

RayOracle::LocalRay RayOracle::local_ray(const Point2& image) const {
  const hsr::Ray3 ray = view_.ray_through(image);
  return {ray.origin - origin_, ray.direction};
}

std::optional<RayOracle::Hit> RayOracle::hit(const Face& face, const LocalRay& ray,
                                             bool measure) const {
  if (!face.usable) return std::nullopt;
  const glm::dvec3& origin = ray.origin;
  const double denominator = glm::dot(face.normal, ray.direction);
  if (denominator == 0.0) return std::nullopt;
  const double t = glm::dot(face.normal, face.point - origin) / denominator;
  if (view_.is_perspective() && !(t > 0.0)) return std::nullopt;
  const glm::dvec3 p = origin + t * ray.direction;
  Hit result;
  result.depth = glm::dot(p, view_.forward());
  // Rounding of t: a few ulps of the lengths involved, divided by the cosine of the angle
  // between the ray and the plane's normal (a plane seen almost edge-on moves its hit
  // far along the ray for a tiny change).
  const double direction_length = glm::length(ray.direction);
  const double cosine = std::fabs(denominator) / direction_length;
  result.uncertainty =
      16.0 * 0x1p-53 *
      (std::fabs(t) * direction_length + glm::length(face.point - origin) + glm::length(origin)) /
      cosine;
  if (!measure) return result;
  const Point2 q = to_chart(face, p);
  const double m = tolerance_.margin;
  if (q.x < face.xmin - m || q.x > face.xmax + m || q.y < face.ymin - m || q.y > face.ymax + m) {
    result.inside = false;
    result.boundary_distance = std::numeric_limits<double>::infinity();
    return result;
  }
  result.inside = crosses_odd(face.chart_loops, q);
  result.boundary_distance = std::numeric_limits<double>::infinity();
  for (const clipper::Loop2& loop : face.chart_loops) {
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      result.boundary_distance =
          std::min(result.boundary_distance, segment_distance(q, loop[j], loop[i]));
    }
  }
  return result;
}

RayAnswer RayOracle::at(const Point2& image) const {
  const double tie = tolerance_.depth;
  const double near = view_.near();
  struct ClearHit {
    std::size_t index;
    double depth, slack;
  };
  std::vector<ClearHit> clear;
  double nearest = std::numeric_limits<double>::infinity(), nearest_slack = 0.0;
  double nearest_unclear = std::numeric_limits<double>::infinity();
  const LocalRay ray = local_ray(image);
  for (std::size_t i = 0; i < faces_.size(); ++i) {
    const std::optional<Hit> h = hit(faces_[i], ray, true);
    if (!h) continue;
    const double slack = tie + h->uncertainty;
    bool unclear = h->boundary_distance < tolerance_.margin + h->uncertainty;
    if (view_.is_perspective()) {
      if (h->depth < near - slack) continue;  // between the eye and the near plane: not seen
      if (h->depth <= near + slack && (h->inside || unclear)) unclear = true;
    }
    if (unclear) {
      nearest_unclear = std::min(nearest_unclear, h->depth - slack);
    } else if (h->inside) {
      clear.push_back({i, h->depth, slack});
      if (h->depth < nearest) {
        nearest = h->depth;
        nearest_slack = slack;
      }
    }
  }
  RayAnswer answer;
  answer.depth = nearest;
  answer.ambiguous = nearest_unclear < nearest + nearest_slack;
  for (const ClearHit& c : clear) {
    if (c.depth - c.slack <= nearest + nearest_slack) answer.nearest.push_back(c.index);
  }
  return answer;
}

std::optional<double> RayOracle::plane_depth(std::size_t index, const Point2& image) const {
  const std::optional<Hit> h = hit(faces_[index], local_ray(image), false);
  if (!h) return std::nullopt;
  return h->depth;
}

std::optional<glm::dvec3> RayOracle::interior_point(std::size_t index, std::mt19937_64& rng) const {
  const Face& face = faces_[index];
  if (!face.usable) return std::nullopt;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const Point2 q{face.xmin + u(rng) * (face.xmax - face.xmin),
                   face.ymin + u(rng) * (face.ymax - face.ymin)};
    if (!crosses_odd(face.chart_loops, q)) continue;
    double distance = std::numeric_limits<double>::infinity();
    for (const clipper::Loop2& loop : face.chart_loops) {
      for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        distance = std::min(distance, segment_distance(q, loop[j], loop[i]));
      }
    }
    if (distance < 10.0 * tolerance_.margin) continue;
    // Lift onto the plane: solve normal · (p − point) = 0 for the dropped coordinate.
    const int i = (face.drop + 1) % 3, j = (face.drop + 2) % 3, k = face.drop;
    glm::dvec3 p(0.0);
    p[i] = q.x;
    p[j] = q.y;
    p[k] = face.point[k] -
           (face.normal[i] * (q.x - face.point[i]) + face.normal[j] * (q.y - face.point[j])) /
               face.normal[k];
    return origin_ + p;
  }
  return std::nullopt;
}

}  // namespace shadowgen::test
