#include "depth_map.h"

namespace shadowgen::sampled::detail {

Frame frame_along(const glm::dvec3& forward) {
  Frame f;
  f.forward = glm::normalize(forward);
  const glm::dvec3 hint = std::fabs(f.forward.z) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  f.right = glm::normalize(glm::cross(f.forward, hint));
  f.up = glm::cross(f.right, f.forward);
  return f;
}

void DepthMap::draw(std::span<const glm::dvec2> poly, const TexelBox& box, double a, double b,
                    double c) {
  if (!(box.u1 >= 0.0 && box.u0 <= nx_ && box.v1 >= 0.0 && box.v0 <= ny_)) return;
  // Clamped as doubles first: the images of triangles cut at a tiny near distance reach
  // far beyond the range of int.
  const int j0 = std::max(0, to_texel(std::ceil(box.v0 - 0.5), ny_));
  const int j1 = std::min(ny_ - 1, to_texel(std::floor(box.v1 - 0.5), ny_));
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
    const int i0 = std::max(0, to_texel(std::ceil(xl - 0.5), nx_));
    const int i1 = std::min(nx_ - 1, to_texel(std::floor(xr - 0.5), nx_));
    for (int i = i0; i <= i1; ++i) {
      float& slot = nearness_[static_cast<std::size_t>(j) * nx_ + i];
      slot = std::max(slot, static_cast<float>(a * (i + 0.5) + b * y + c));
    }
  }
}

}  // namespace shadowgen::sampled::detail
