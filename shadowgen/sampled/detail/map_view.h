#pragma once

// One view of a light in a shadow map (shadow_map.h): its frame, its depth map, the
// depths stored and the lit test of a point against them, percentage-closer filtered.
// Defined here for shadow_map.cpp, the only file that holds views.

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>

#include "depth_map.h"
#include "shadowgen/sampled/shadow_map.h"

namespace shadowgen::sampled {
namespace detail {

// The depth bias's floor, relative to the depth stored: a few times the float's rounding
// (2^-24), so that a part's own texels pass however small the texels of a face's map.
constexpr double kFloatSlack = 0x1p-21;

}  // namespace detail

// One view of the light: its frame, where depths are measured from, the map's place in the
// image plane and its texels. Image coordinates are (x, y) in the frame (orthographic) or
// (x/z, y/z) (perspective); texel coordinates u = (x − x0) / tx, v = (y − y0) / ty.
struct ShadowMap::View {
  detail::Frame frame;
  glm::dvec3 origin{0.0};  // orthographic: on the occluders' box's middle; perspective: the light
  bool perspective = false;
  double x0 = 0.0, y0 = 0.0;  // the image coordinates of the map's corner
  double tx = 1.0, ty = 1.0;  // a texel's extent in image coordinates
  detail::DepthMap map{1, 1};

  glm::dvec2 image(const glm::dvec3& e) const {
    const double x = perspective ? e.x / e.z : e.x, y = perspective ? e.y / e.z : e.y;
    return {(x - x0) / tx, (y - y0) / ty};
  }

  // A texel's widths at depth z.
  glm::dvec2 texel_at(double z) const {
    return perspective ? glm::dvec2(z * tx, z * ty) : glm::dvec2(tx, ty);
  }

  // The triangle (in the frame, relative to the origin) drawn into the map; its box in
  // texel coordinates, or nullopt where it covers nothing (seen edge-on, or wholly behind
  // a perspective view's `near` distance).
  std::optional<detail::TexelBox> draw(const std::array<glm::dvec3, 3>& t, double near) {
    const glm::dvec3 nrm = glm::cross(t[1] - t[0], t[2] - t[0]);
    const double off = glm::dot(nrm, t[0]);  // the plane nrm · e = off
    std::array<glm::dvec2, 4> poly;
    std::size_t count = 0;
    detail::TexelBox box;
    if (!perspective) {
      if (nrm.z == 0.0) return std::nullopt;  // edge-on: no area in the image
      for (const glm::dvec3& e : t) box.add(poly[count++] = image(e));
      // nearness −z = −(off − nrm.x·x − nrm.y·y) / nrm.z with x = x0 + u·tx, y = y0 + v·ty.
      map.draw(std::span(poly.data(), count), box, nrm.x * tx / nrm.z, nrm.y * ty / nrm.z,
               (nrm.x * x0 + nrm.y * y0 - off) / nrm.z);
      return box;
    }
    if (off == 0.0) return std::nullopt;  // the light in the triangle's plane: seen edge-on
    // Cut at z = near (Sutherland–Hodgman on one plane): a triangle gives at most four.
    for (std::size_t m = 0; m < 3; ++m) {
      const glm::dvec3& p = t[m];
      const glm::dvec3& q = t[(m + 1) % 3];
      if (p.z >= near) box.add(poly[count++] = image(p));
      if ((p.z >= near) != (q.z >= near))
        box.add(poly[count++] = image(p + (q - p) * ((near - p.z) / (q.z - p.z))));
    }
    if (count < 3) return std::nullopt;
    // 1/z = (nrm.x·x' + nrm.y·y' + nrm.z) / off on the plane, x' = x0 + u·tx, y' = y0 + v·ty.
    map.draw(std::span(poly.data(), count), box, nrm.x * tx / off, nrm.y * ty / off,
             (nrm.z + nrm.x * x0 + nrm.y * y0) / off);
    return box;
  }

  // The depth of the plane nrm · e = off on the ray (orthographic: the line) through the
  // centre of texel (i, j); +∞ where the ray misses it (beyond its horizon) or runs in it.
  double plane_depth(int i, int j, const glm::dvec3& nrm, double off) const {
    const double x = x0 + (i + 0.5) * tx, y = y0 + (j + 0.5) * ty;
    if (!perspective) {
      if (nrm.z == 0.0) return INFINITY;
      return (off - nrm.x * x - nrm.y * y) / nrm.z;
    }
    const double depth = off / (nrm.x * x + nrm.y * y + nrm.z);
    return depth > 0.0 && std::isfinite(depth) ? depth : INFINITY;
  }

  // The depth stored at texel (i, j); +∞ where empty.
  double stored_depth(int i, int j) const {
    const float nearness = map.at(i, j);
    if (nearness == detail::kEmpty) return INFINITY;
    return perspective ? 1.0 / static_cast<double>(nearness) : -static_cast<double>(nearness);
  }

  // The lit fraction of the point `e` (in the frame, relative to the origin) on a part of
  // unit normal `nrm` (in the frame): 3×3 percentage-closer filtering, as shadow_map.h says.
  // `own`, where given, is cleared unless every tap shows the part's own plane (the depth
  // stored there within the bias of the plane's), which lights the point for certain.
  double lit(const glm::dvec3& e, const glm::dvec3& nrm, bool* own = nullptr) const {
    if (perspective && !(e.z > 0.0)) return 1.0;  // the sample at the light
    const double off = glm::dot(nrm, e);          // the part's plane: nrm · e = off
    const glm::dvec2 texel = texel_at(e.z);
    // The part's plane is followed to a tap no farther than kPlaneReachTexels behind the
    // sample (the slope clamp), all the way towards the light.
    const double farthest = e.z + kPlaneReachTexels * std::max(texel.x, texel.y);
    const glm::dvec2 at = image(e);
    const int nx = map.width(), ny = map.height();
    const int ib =
        std::clamp(static_cast<int>(std::floor(std::clamp(at.x, -1.0, double(nx)))), 0, nx - 1);
    const int jb =
        std::clamp(static_cast<int>(std::floor(std::clamp(at.y, -1.0, double(ny)))), 0, ny - 1);
    int passed = 0;
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        const int i = std::clamp(ib + di, 0, nx - 1), j = std::clamp(jb + dj, 0, ny - 1);
        const double stored = stored_depth(i, j);
        if (stored == INFINITY) {
          if (own != nullptr) *own = false;
          ++passed;
          continue;
        }
        const double bias = std::max(kDepthBiasTexels * std::min(texel.x, texel.y),
                                     detail::kFloatSlack * std::fabs(stored));
        const double plane = plane_depth(i, j, nrm, off);
        if (own != nullptr && !(std::fabs(plane - stored) <= bias)) *own = false;
        if (std::min(plane, farthest) <= stored + bias) ++passed;
      }
    }
    return passed / 9.0;
  }
};

}  // namespace shadowgen::sampled
