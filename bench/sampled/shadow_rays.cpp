#include "bench/sampled/shadow_rays.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>

#include "hsr/polygon3.h"
#include "shadowgen/sampled/face_samples.h"
#include "shadowgen/sampled/part_triangles.h"
#include "shadowgen/shadows/light_scope.h"

namespace shadowgen::bench {
namespace {

struct Triangle {
  glm::dvec3 a, e1, e2;  // a, b − a, c − a
};

struct Node {
  glm::dvec3 lo, hi;
  int left = -1, right = -1;  // children, or -1 for a leaf
  int first = 0, count = 0;   // leaf: triangles [first, first + count)
};

class Bvh {
 public:
  explicit Bvh(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
    order_.resize(triangles_.size());
    std::iota(order_.begin(), order_.end(), 0);
    if (!triangles_.empty()) build(0, static_cast<int>(order_.size()));
    std::vector<Triangle> sorted;
    sorted.reserve(triangles_.size());
    for (int i : order_) sorted.push_back(triangles_[static_cast<std::size_t>(i)]);
    triangles_ = std::move(sorted);
  }

  bool empty() const { return nodes_.empty(); }

  // Does the segment o + t·d, t in (tmin, tmax), cross a triangle?
  bool any_hit(const glm::dvec3& o, const glm::dvec3& d, double tmin, double tmax) const {
    if (nodes_.empty()) return false;
    const glm::dvec3 inv(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
    int stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
      if (!box_hit(node, o, inv, tmin, tmax)) continue;
      if (node.left < 0) {
        for (int i = node.first; i < node.first + node.count; ++i) {
          if (triangle_hit(triangles_[static_cast<std::size_t>(i)], o, d, tmin, tmax)) return true;
        }
      } else {
        stack[top++] = node.left;
        stack[top++] = node.right;
      }
    }
    return false;
  }

 private:
  static bool box_hit(const Node& n, const glm::dvec3& o, const glm::dvec3& inv, double tmin,
                      double tmax) {
    for (int a = 0; a < 3; ++a) {
      double t0 = (n.lo[a] - o[a]) * inv[a], t1 = (n.hi[a] - o[a]) * inv[a];
      if (t0 > t1) std::swap(t0, t1);
      if (std::isnan(t0) || std::isnan(t1)) continue;  // o on a slab plane, d parallel to it
      tmin = std::max(tmin, t0);
      tmax = std::min(tmax, t1);
      if (tmin > tmax) return false;
    }
    return true;
  }

  // Möller–Trumbore; edges and vertices count as hits.
  static bool triangle_hit(const Triangle& t, const glm::dvec3& o, const glm::dvec3& d, double tmin,
                           double tmax) {
    const glm::dvec3 p = glm::cross(d, t.e2);
    const double det = glm::dot(t.e1, p);
    if (det == 0.0) return false;  // the segment parallel to the triangle
    const double inv = 1.0 / det;
    const glm::dvec3 s = o - t.a;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, t.e1);
    const double v = glm::dot(d, q) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    const double tt = glm::dot(t.e2, q) * inv;
    return tt > tmin && tt < tmax;
  }

  int build(int first, int count) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo), clo(lo), chi(-lo);
    for (int i = first; i < first + count; ++i) {
      const Triangle& t = triangles_[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])];
      for (const glm::dvec3& v : {t.a, t.a + t.e1, t.a + t.e2}) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
      const glm::dvec3 c = t.a + (t.e1 + t.e2) / 3.0;
      clo = glm::min(clo, c);
      chi = glm::max(chi, c);
    }
    nodes_[static_cast<std::size_t>(id)].lo = lo;
    nodes_[static_cast<std::size_t>(id)].hi = hi;
    if (count <= 4) {
      nodes_[static_cast<std::size_t>(id)].first = first;
      nodes_[static_cast<std::size_t>(id)].count = count;
      return id;
    }
    const glm::dvec3 ext = chi - clo;
    const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    const auto begin = order_.begin() + first, mid = begin + count / 2, end = begin + count;
    std::nth_element(begin, mid, end, [&](int a, int b) {
      const Triangle& ta = triangles_[static_cast<std::size_t>(a)];
      const Triangle& tb = triangles_[static_cast<std::size_t>(b)];
      return (3.0 * ta.a + ta.e1 + ta.e2)[axis] < (3.0 * tb.a + tb.e1 + tb.e2)[axis];
    });
    const int left = build(first, count / 2);
    const int right = build(first + count / 2, count - count / 2);
    nodes_[static_cast<std::size_t>(id)].left = left;
    nodes_[static_cast<std::size_t>(id)].right = right;
    return id;
  }

  std::vector<Triangle> triangles_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace

std::vector<double> double_ray_lit_areas(const Scene& scene, const Light& light,
                                         std::span<const std::size_t> faces, int samples) {
  const ScenePartPlanes all(scene);
  const std::vector<std::size_t>& first = all.first;  // face f's parts: [first[f], first[f + 1])
  std::vector<sampled::PartTriangles> parts;
  for (const hsr::Polygon3& part : all.polygons) parts.push_back(sampled::part_triangles(part));
  const std::vector<PartRole> roles = part_roles(all.polygons, all.planes, light);
  std::vector<Triangle> triangles;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (!occludes(roles[i])) continue;
    for (const sampled::Triangle3& t : parts[i].triangles) {
      triangles.push_back({t.a, t.b - t.a, t.c - t.a});
      for (const glm::dvec3& v : {t.a, t.b, t.c}) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
    }
  }
  const Bvh bvh(std::move(triangles));
  // A directional light's ray runs twice the occluders' diagonal: past every one of them.
  const double reach = bvh.empty() ? 1.0 : 2.0 * glm::length(hi - lo) + 1.0;

  std::vector<double> areas;
  std::vector<sampled::FaceSample> points;
  std::vector<double> lit;
  for (std::size_t f : faces) {
    const std::span<const sampled::PartTriangles> face(parts.data() + first[f],
                                                       first[f + 1] - first[f]);
    sampled::face_samples(face, samples, f, points);
    lit.assign(points.size(), 0.0);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (roles[first[f] + points[i].part] != PartRole::kFacing) continue;
      const glm::dvec3& p = points[i].point;
      const glm::dvec3 d = light.type == LightType::kDirectional
                               ? glm::normalize(-light.direction) * reach
                               : light.position - p;
      lit[i] = bvh.any_hit(p, d, 1e-9, 1.0) ? 0.0 : 1.0;
    }
    double area = 0.0;
    for (double a : sampled::part_lit_areas(face, points, lit)) area += a;
    areas.push_back(area);
  }
  return areas;
}

}  // namespace shadowgen::bench
