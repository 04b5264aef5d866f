#include "bench/sampled/shadow_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>

#include "bench/sampled/face_samples.h"
#include "bench/sampled/light_scope.h"

namespace shadowgen::bench {
namespace {

constexpr float kEmpty = -std::numeric_limits<float>::infinity();

// One depth map storing the largest "nearness" (a value growing towards the light, affine
// in image coordinates on a plane) per texel.
struct DepthMap {
  int size = 0;
  std::vector<float> nearness;

  explicit DepthMap(int n) : size(n), nearness(static_cast<std::size_t>(n) * n, kEmpty) {}
  float& at(int i, int j) { return nearness[static_cast<std::size_t>(j) * size + i]; }
  int to_texel(double v) const {
    return static_cast<int>(std::clamp(v, -1.0, static_cast<double>(size)));
  }

  // Rasterises a convex polygon given in texel coordinates (texel (i, j) has its centre
  // at (i + 0.5, j + 0.5)); nearness = a·x + b·y + c over it.
  void draw(const std::vector<glm::dvec2>& poly, double a, double b, double c) {
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (const glm::dvec2& p : poly) {
      xmin = std::min(xmin, p.x);
      xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y);
      ymax = std::max(ymax, p.y);
    }
    if (xmax < 0.0 || xmin > size || ymax < 0.0 || ymin > size) return;
    // Clamped as doubles first: images of polygons cut at a tiny near plane reach far
    // beyond the range of int.
    const int j0 = std::max(0, to_texel(std::ceil(ymin - 0.5)));
    const int j1 = std::min(size - 1, to_texel(std::floor(ymax - 0.5)));
    for (int j = j0; j <= j1; ++j) {
      const double y = j + 0.5;
      double xl = INFINITY, xr = -INFINITY;
      for (std::size_t m = 0, n = poly.size(); m < n; ++m) {
        const glm::dvec2& p = poly[m];
        const glm::dvec2& q = poly[(m + 1) % n];
        if ((p.y <= y && y <= q.y) || (q.y <= y && y <= p.y)) {
          const double x = p.y == q.y ? p.x : p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
          xl = std::min(xl, p.y == q.y ? std::min(p.x, q.x) : x);
          xr = std::max(xr, p.y == q.y ? std::max(p.x, q.x) : x);
        }
      }
      if (!(xl <= xr)) continue;
      const int i0 = std::max(0, to_texel(std::ceil(xl - 0.5)));
      const int i1 = std::min(size - 1, to_texel(std::floor(xr - 0.5)));
      for (int i = i0; i <= i1; ++i) {
        const float v = static_cast<float>(a * (i + 0.5) + b * y + c);
        float& slot = at(i, j);
        slot = std::max(slot, v);
      }
    }
  }
};

struct Frame {
  glm::dvec3 right, up, forward;
  glm::dvec3 to(const glm::dvec3& d) const {
    return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
  }
};

Frame frame_along(const glm::dvec3& forward, const glm::dvec3& hint) {
  Frame f;
  f.forward = glm::normalize(forward);
  f.right = glm::normalize(glm::cross(f.forward, hint));
  f.up = glm::cross(f.right, f.forward);
  return f;
}

double bias_factor(const ConvexFace& face, const glm::dvec3& to_light) {
  const double c = std::fabs(glm::dot(face.normal, glm::normalize(to_light)));
  const double tan_theta = std::sqrt(std::max(0.0, 1.0 - c * c)) / std::max(c, 1e-12);
  return 1.0 + std::min(tan_theta, 10.0);
}

// Directional light: one orthographic map along the light, nearness = −depth.
class OrthoMap {
 public:
  OrthoMap(const LightScope& scope, const Light& light, int n)
      : frame_(frame_along(light.direction, std::fabs(light.direction.z) > 0.9
                                                ? glm::dvec3(1, 0, 0)
                                                : glm::dvec3(0, 0, 1))),
        centre_(0.5 * (scope.lo + scope.hi)),
        map_(n) {
    double ext = 0.0;
    for (std::size_t f = 0; f < scope.faces.size(); ++f) {
      if (!scope.present[f]) continue;
      for (const glm::dvec3& v : scope.faces[f].loop) {
        const glm::dvec3 e = frame_.to(v - centre_);
        ext = std::max({ext, std::fabs(e.x), std::fabs(e.y)});
      }
    }
    texel_ = 2.0 * ext * (1.0 + 1e-9) / n;
    half_ = 0.5 * n;
    std::vector<glm::dvec2> poly;
    for (std::size_t f = 0; f < scope.faces.size(); ++f) {
      if (!scope.present[f]) continue;
      const ConvexFace& face = scope.faces[f];
      const glm::dvec3 nrm = frame_.to(face.normal);
      if (nrm.z == 0.0) continue;  // edge-on: no area in the map
      // Plane: nrm · e = off, e in the frame; depth e.z = (off − nrm.x e.x − nrm.y e.y) / nrm.z
      const double off = glm::dot(nrm, frame_.to(face.loop[0] - centre_));
      poly.clear();
      for (const glm::dvec3& v : face.loop) {
        const glm::dvec3 e = frame_.to(v - centre_);
        poly.push_back({e.x / texel_ + half_, e.y / texel_ + half_});
      }
      // e.x = (x − half)·texel; nearness = −e.z, affine in texel coordinates (x, y).
      const double a = nrm.x * texel_ / nrm.z, b = nrm.y * texel_ / nrm.z;
      const double c = -(off - nrm.x * (-half_ * texel_) - nrm.y * (-half_ * texel_)) / nrm.z;
      map_.draw(poly, a, b, c);
    }
  }

  bool lit(const glm::dvec3& p, double bias_texels) {
    const glm::dvec3 e = frame_.to(p - centre_);
    const int i = std::clamp(static_cast<int>(std::floor(e.x / texel_ + half_)), 0, map_.size - 1);
    const int j = std::clamp(static_cast<int>(std::floor(e.y / texel_ + half_)), 0, map_.size - 1);
    const float stored = map_.at(i, j);
    return stored == kEmpty || e.z <= -static_cast<double>(stored) + bias_texels * texel_;
  }

 private:
  Frame frame_;
  glm::dvec3 centre_;
  DepthMap map_;
  double texel_ = 1.0, half_ = 0.0;
};

// Point light: six 90° perspective maps, image (x/z, y/z) in [−1, 1]², nearness 1/z.
class CubeMap {
 public:
  CubeMap(const LightScope& scope, const Light& light, int n) : eye_(light.position) {
    static const std::array<glm::dvec3, 6> kAxes = {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0),
                                                    glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0),
                                                    glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)};
    const double near = 1e-9 * glm::length(scope.hi - scope.lo);
    std::vector<glm::dvec3> clipped;
    std::vector<glm::dvec2> poly;
    for (const glm::dvec3& axis : kAxes) {
      frames_.push_back(
          frame_along(axis, std::fabs(axis.z) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1)));
      maps_.emplace_back(n);
      const Frame& fr = frames_.back();
      DepthMap& map = maps_.back();
      const double s = 0.5 * n;  // texel x = (x/z + 1)·s
      for (std::size_t f = 0; f < scope.faces.size(); ++f) {
        if (!scope.present[f]) continue;
        const ConvexFace& face = scope.faces[f];
        const glm::dvec3 nrm = fr.to(face.normal);
        const double off = glm::dot(nrm, fr.to(face.loop[0] - eye_));
        if (off == 0.0) continue;  // the light in the face's plane: seen edge-on
        // Clip to z >= near (Sutherland–Hodgman, one plane).
        clipped.clear();
        for (std::size_t m = 0, k = face.loop.size(); m < k; ++m) {
          const glm::dvec3 p = fr.to(face.loop[m] - eye_);
          const glm::dvec3 q = fr.to(face.loop[(m + 1) % k] - eye_);
          if (p.z >= near) clipped.push_back(p);
          if ((p.z >= near) != (q.z >= near)) {
            clipped.push_back(p + (q - p) * ((near - p.z) / (q.z - p.z)));
          }
        }
        if (clipped.size() < 3) continue;
        poly.clear();
        for (const glm::dvec3& e : clipped)
          poly.push_back({(e.x / e.z + 1.0) * s, (e.y / e.z + 1.0) * s});
        // On the plane nrm · e = off with e = z (x', y', 1): 1/z = (nrm.x x' + nrm.y y' +
        // nrm.z) / off, and x' = X/s − 1 in texel coordinates X.
        const double a = nrm.x / (s * off), b = nrm.y / (s * off);
        const double c = (nrm.z - nrm.x - nrm.y) / off;
        map.draw(poly, a, b, c);
      }
    }
  }

  bool lit(const glm::dvec3& p, double bias_texels) {
    const glm::dvec3 d = p - eye_;
    const glm::dvec3 ad = glm::abs(d);
    const int axis = ad.x >= ad.y && ad.x >= ad.z ? (d.x > 0 ? 0 : 1)
                     : ad.y >= ad.z               ? (d.y > 0 ? 2 : 3)
                                                  : (d.z > 0 ? 4 : 5);
    const glm::dvec3 e = frames_[axis].to(d);
    DepthMap& map = maps_[axis];
    const double s = 0.5 * map.size;
    const int i = std::clamp(static_cast<int>(std::floor((e.x / e.z + 1.0) * s)), 0, map.size - 1);
    const int j = std::clamp(static_cast<int>(std::floor((e.y / e.z + 1.0) * s)), 0, map.size - 1);
    const float stored = map.at(i, j);
    if (stored == kEmpty || stored <= 0.0f) return true;
    const double texel = e.z / s;  // a texel's width at the sample's depth
    return e.z <= 1.0 / static_cast<double>(stored) + bias_texels * texel;
  }

 private:
  glm::dvec3 eye_;
  std::vector<Frame> frames_;
  std::vector<DepthMap> maps_;
};

template <class Map>
std::vector<double> estimate(const LightScope& scope, const Light& light, Map& map, int k) {
  return sampled_lit_areas(scope, k, [&](const glm::dvec3& p, const ConvexFace& face) {
    return map.lit(p, bias_factor(face, towards_light(light, p)));
  });
}

}  // namespace

std::vector<double> shadow_map_lit_areas(const Scene& scene, const Light& light, int map_size,
                                         int k) {
  const LightScope scope = light_scope(scene, light);
  if (light.type == LightType::kDirectional) {
    OrthoMap map(scope, light, map_size);
    return estimate(scope, light, map, k);
  }
  CubeMap map(scope, light, map_size);
  return estimate(scope, light, map, k);
}

}  // namespace shadowgen::bench
