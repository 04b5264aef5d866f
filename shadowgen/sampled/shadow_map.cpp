#include "shadowgen/sampled/shadow_map.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <vector>

namespace shadowgen::sampled {
namespace {

constexpr float kEmpty = -std::numeric_limits<float>::infinity();

struct Frame {
  glm::dvec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, 1};
  glm::dvec3 to(const glm::dvec3& d) const {
    return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
  }
};

Frame frame_along(const glm::dvec3& forward) {
  Frame f;
  f.forward = glm::normalize(forward);
  const glm::dvec3 hint = std::fabs(f.forward.z) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  f.right = glm::normalize(glm::cross(f.forward, hint));
  f.up = glm::cross(f.right, f.forward);
  return f;
}

// One map of "nearness" per texel: a value that grows towards the light and is affine in
// the image over a plane (−depth for an orthographic view, 1/z for a perspective one), so
// that a triangle is drawn by evaluating one affine function; the largest is kept.
class DepthMap {
 public:
  explicit DepthMap(int n) : size_(n), nearness_(static_cast<std::size_t>(n) * n, kEmpty) {}

  int size() const { return size_; }
  float at(int i, int j) const { return nearness_[static_cast<std::size_t>(j) * size_ + i]; }

  // Covers the texels whose centres (i + 0.5, j + 0.5) lie in the convex polygon `poly`
  // (texel coordinates, edges included) with nearness a·x + b·y + c.
  void draw(std::span<const glm::dvec2> poly, double a, double b, double c) {
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (const glm::dvec2& p : poly) {
      xmin = std::min(xmin, p.x);
      xmax = std::max(xmax, p.x);
      ymin = std::min(ymin, p.y);
      ymax = std::max(ymax, p.y);
    }
    if (!(xmax >= 0.0 && xmin <= size_ && ymax >= 0.0 && ymin <= size_)) return;
    // Clamped as doubles first: the images of triangles cut at a tiny near distance reach
    // far beyond the range of int.
    const int j0 = std::max(0, to_texel(std::ceil(ymin - 0.5)));
    const int j1 = std::min(size_ - 1, to_texel(std::floor(ymax - 0.5)));
    for (int j = j0; j <= j1; ++j) {
      const double y = j + 0.5;
      double xl = INFINITY, xr = -INFINITY;
      for (std::size_t m = 0, n = poly.size(); m < n; ++m) {
        const glm::dvec2& p = poly[m];
        const glm::dvec2& q = poly[(m + 1) % n];
        if (!((p.y <= y && y <= q.y) || (q.y <= y && y <= p.y))) continue;
        if (p.y == q.y) {
          xl = std::min({xl, p.x, q.x});
          xr = std::max({xr, p.x, q.x});
        } else {
          const double x = p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
          xl = std::min(xl, x);
          xr = std::max(xr, x);
        }
      }
      if (!(xl <= xr)) continue;
      const int i0 = std::max(0, to_texel(std::ceil(xl - 0.5)));
      const int i1 = std::min(size_ - 1, to_texel(std::floor(xr - 0.5)));
      for (int i = i0; i <= i1; ++i) {
        float& slot = nearness_[static_cast<std::size_t>(j) * size_ + i];
        slot = std::max(slot, static_cast<float>(a * (i + 0.5) + b * y + c));
      }
    }
  }

 private:
  int to_texel(double v) const { return static_cast<int>(std::clamp(v, -1.0, double(size_))); }

  int size_;
  std::vector<float> nearness_;
};

}  // namespace

// One view of the light: its frame, where it is measured from, and its map.
struct ShadowMap::View {
  Frame frame;
  glm::dvec3 origin{0.0};    // orthographic: the occluders' box's middle; perspective: the light
  bool perspective = false;  // image (x/z, y/z) / spread in [−1, 1]², else (x, y) / texel
  double texel = 1.0;        // orthographic: a texel's width
  double spread = 1.0;       // perspective: the map's half-width in x/z (a margin past 1)
  double half = 0.0;         // half the resolution
  DepthMap map{1};

  glm::dvec2 image(const glm::dvec3& e) const {
    if (perspective) {
      return {(e.x / (e.z * spread) + 1.0) * half, (e.y / (e.z * spread) + 1.0) * half};
    }
    return {e.x / texel + half, e.y / texel + half};
  }

  // A texel's width at depth z.
  double texel_at(double z) const { return perspective ? z * spread / half : texel; }

  // The triangle (in the frame, relative to the origin) drawn into the map. `near`: the
  // perspective view's near distance.
  void draw(const std::array<glm::dvec3, 3>& t, double near) {
    const glm::dvec3 nrm = glm::cross(t[1] - t[0], t[2] - t[0]);
    const double off = glm::dot(nrm, t[0]);  // the plane nrm · e = off
    std::array<glm::dvec2, 4> poly;
    std::size_t count = 0;
    if (!perspective) {
      if (nrm.z == 0.0) return;  // edge-on: no area in the image
      for (const glm::dvec3& e : t) poly[count++] = image(e);
      // nearness −z = −(off − nrm.x·e.x − nrm.y·e.y) / nrm.z with e.x = (x − half)·texel.
      map.draw(std::span(poly.data(), count), nrm.x * texel / nrm.z, nrm.y * texel / nrm.z,
               -(off + (nrm.x + nrm.y) * half * texel) / nrm.z);
      return;
    }
    if (off == 0.0) return;  // the light in the triangle's plane: seen edge-on
    // Cut at z = near (Sutherland–Hodgman on one plane): a triangle gives at most four.
    for (std::size_t m = 0; m < 3; ++m) {
      const glm::dvec3& p = t[m];
      const glm::dvec3& q = t[(m + 1) % 3];
      if (p.z >= near) poly[count++] = image(p);
      if ((p.z >= near) != (q.z >= near))
        poly[count++] = image(p + (q - p) * ((near - p.z) / (q.z - p.z)));
    }
    if (count < 3) return;
    // 1/z = (nrm.x·x' + nrm.y·y' + nrm.z) / off on the plane, x' = (x / half − 1)·spread.
    const double s = spread / (half * off);
    map.draw(std::span(poly.data(), count), nrm.x * s, nrm.y * s,
             (nrm.z - (nrm.x + nrm.y) * spread) / off);
  }

  // The depth of the plane nrm · e = off on the ray (orthographic: the line) through the
  // centre of texel (i, j); +∞ where the ray misses it (beyond its horizon) or runs in it.
  double plane_depth(int i, int j, const glm::dvec3& nrm, double off) const {
    const double x = i + 0.5, y = j + 0.5;
    if (!perspective) {
      if (nrm.z == 0.0) return INFINITY;
      return (off - nrm.x * (x - half) * texel - nrm.y * (y - half) * texel) / nrm.z;
    }
    const double denominator =
        (nrm.x * (x / half - 1.0) + nrm.y * (y / half - 1.0)) * spread + nrm.z;
    const double depth = off / denominator;
    return depth > 0.0 && std::isfinite(depth) ? depth : INFINITY;
  }

  // The depth stored at texel (i, j); +∞ where empty.
  double stored_depth(int i, int j) const {
    const float nearness = map.at(i, j);
    if (nearness == kEmpty) return INFINITY;
    return perspective ? 1.0 / static_cast<double>(nearness) : -static_cast<double>(nearness);
  }
};

ShadowMap::ShadowMap(const Light& light, std::span<const Triangle3> occluders, int resolution) {
  perspective_ = light.type == LightType::kPoint;
  view_count_ = perspective_ ? 6 : 1;
  views_ = std::make_unique<View[]>(static_cast<std::size_t>(view_count_));
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const Triangle3& t : occluders) {
    for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
      lo = glm::min(lo, *v);
      hi = glm::max(hi, *v);
    }
  }
  const double diagonal = occluders.empty() ? 0.0 : glm::length(hi - lo);
  // Each map reaches kMarginTexels past what it must show (the box of the occluders, a
  // cube face's 90°), as a fraction of its half-width: so that a sample at its edge, at a
  // cube map's seam included, is filtered with texels that hold what the light sees there
  // rather than the edge's own texels repeated.
  const double margin = 2.0 * kMarginTexels / resolution;
  if (perspective_) {
    eye_ = light.position;
    static const std::array<glm::dvec3, 6> kAxes = {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0),
                                                    glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0),
                                                    glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)};
    for (int k = 0; k < 6; ++k) {
      View& view = views_[k];
      view.frame = frame_along(kAxes[k]);
      view.origin = eye_;
      view.perspective = true;
      view.spread = 1.0 + margin;
    }
  } else {
    View& view = views_[0];
    view.frame = frame_along(light.direction);
    view.origin = occluders.empty() ? glm::dvec3(0.0) : 0.5 * (lo + hi);
    double extent = 0.0;
    for (const Triangle3& t : occluders) {
      for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
        const glm::dvec3 e = view.frame.to(*v - view.origin);
        extent = std::max({extent, std::fabs(e.x), std::fabs(e.y)});
      }
    }
    // A hair wider than the box, so that its outermost vertices fall inside the last texel,
    // and the margin.
    if (extent > 0.0) view.texel = 2.0 * extent * (1.0 + 1e-9) * (1.0 + margin) / resolution;
  }
  const double near = std::max(1e-9 * diagonal, DBL_MIN);
  for (int k = 0; k < view_count_; ++k) {
    View& view = views_[k];
    view.half = 0.5 * resolution;
    view.map = DepthMap(resolution);
    for (const Triangle3& t : occluders) {
      view.draw({view.frame.to(t.a - view.origin), view.frame.to(t.b - view.origin),
                 view.frame.to(t.c - view.origin)},
                near);
    }
  }
}

ShadowMap::~ShadowMap() = default;

double ShadowMap::lit(const glm::dvec3& point, const glm::dvec3& normal) const {
  int k = 0;
  if (perspective_) {
    // The cube face the sample's direction from the light falls in: its largest component.
    const glm::dvec3 d = point - eye_;
    const glm::dvec3 a = glm::abs(d);
    k = a.x >= a.y && a.x >= a.z ? (d.x > 0 ? 0 : 1)
        : a.y >= a.z             ? (d.y > 0 ? 2 : 3)
                                 : (d.z > 0 ? 4 : 5);
  }
  const View& view = views_[k];
  const glm::dvec3 e = view.frame.to(point - view.origin);
  if (view.perspective && !(e.z > 0.0)) return 1.0;  // the sample at the light
  const glm::dvec3 nrm = view.frame.to(normal);
  const double off = glm::dot(nrm, e);  // the part's plane: nrm · e = off
  const double texel = view.texel_at(e.z);
  // The part's plane is followed to a tap no farther than kPlaneReachTexels behind the
  // sample (the slope clamp), all the way towards the light.
  const double farthest = e.z + kPlaneReachTexels * texel, bias = kDepthBiasTexels * texel;
  const glm::dvec2 at = view.image(e);
  const int n = view.map.size();
  const int ib =
      std::clamp(static_cast<int>(std::floor(std::clamp(at.x, -1.0, double(n)))), 0, n - 1);
  const int jb =
      std::clamp(static_cast<int>(std::floor(std::clamp(at.y, -1.0, double(n)))), 0, n - 1);
  int passed = 0;
  for (int dj = -1; dj <= 1; ++dj) {
    for (int di = -1; di <= 1; ++di) {
      const int i = std::clamp(ib + di, 0, n - 1), j = std::clamp(jb + dj, 0, n - 1);
      const double stored = view.stored_depth(i, j);
      if (stored == INFINITY ||
          std::min(view.plane_depth(i, j, nrm, off), farthest) <= stored + bias) {
        ++passed;
      }
    }
  }
  return passed / 9.0;
}

}  // namespace shadowgen::sampled
