#include "bench/sampled/light_scope.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>

#include "shadowgen/area.h"

namespace shadowgen::bench {
namespace {

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::distance(p, a + t * ab);
}

double distance_to_face(const glm::dvec3& p, const ConvexFace& f) {
  const double d = glm::dot(p - f.loop[0], f.normal);
  const glm::dvec3 foot = p - d * f.normal;
  bool inside = true;
  for (std::size_t i = 0, n = f.loop.size(); i < n && inside; ++i) {
    const glm::dvec3& a = f.loop[i];
    const glm::dvec3& b = f.loop[(i + 1) % n];
    inside = glm::dot(glm::cross(b - a, foot - a), f.normal) >= 0.0;
  }
  if (inside) return std::fabs(d);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = f.loop.size(); i < n; ++i) {
    best = std::min(best, distance_to_segment(p, f.loop[i], f.loop[(i + 1) % n]));
  }
  return best;
}

}  // namespace

glm::dvec3 towards_light(const Light& light, const glm::dvec3& p) {
  return light.type == LightType::kDirectional ? -light.direction : light.position - p;
}

LightScope light_scope(const Scene& scene, const Light& light) {
  LightScope scope;
  scope.lo = glm::dvec3(std::numeric_limits<double>::infinity());
  scope.hi = -scope.lo;
  for (const Face& face : scene.faces) {
    if (face.parts.size() != 1 || !face.parts[0].holes.empty() || face.parts[0].outer.size() < 3) {
      throw std::invalid_argument("sampled estimators take single convex faces: " + face.id);
    }
    ConvexFace f;
    f.loop = face.parts[0].outer;
    const glm::dvec3 n = glm::cross(f.loop[1] - f.loop[0], f.loop[2] - f.loop[0]);
    f.normal = glm::normalize(n);
    f.area = area(face.parts[0]);
    const bool present = light.type == LightType::kDirectional || !light.range ||
                         distance_to_face(light.position, f) <= light.range->end;
    const double facing = light.type == LightType::kDirectional
                              ? -glm::dot(f.normal, light.direction)
                              : glm::dot(f.normal, light.position - f.loop[0]);
    scope.present.push_back(present);
    scope.receives.push_back(present && facing > 0.0);
    if (present) {
      for (const glm::dvec3& v : f.loop) {
        scope.lo = glm::min(scope.lo, v);
        scope.hi = glm::max(scope.hi, v);
      }
    }
    scope.faces.push_back(std::move(f));
  }
  return scope;
}

}  // namespace shadowgen::bench
