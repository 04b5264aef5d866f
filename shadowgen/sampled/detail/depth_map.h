#pragma once

// The depth maps a shadow map renders (shadowgen/sampled/shadow_map.h): a frame looking
// along a direction, boxes of texel coordinates, and a map of nearness per texel drawn
// one convex polygon at a time.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

namespace shadowgen::sampled::detail {

// A texel no polygon covers.
constexpr float kEmpty = -std::numeric_limits<float>::infinity();

// An orthonormal frame: `to` gives a direction's coordinates in it.
struct Frame {
  glm::dvec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, 1};
  glm::dvec3 to(const glm::dvec3& d) const {
    return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
  }
};

// A frame whose forward is `forward` (normalised; not zero), its right and up
// chosen from the axis least aligned with it.
Frame frame_along(const glm::dvec3& forward);

// An axis-aligned box of texel coordinates.
struct TexelBox {
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  void add(const glm::dvec2& p) {
    u0 = std::min(u0, p.x);
    u1 = std::max(u1, p.x);
    v0 = std::min(v0, p.y);
    v1 = std::max(v1, p.y);
  }
};

// One map of "nearness" per texel: a value that grows towards the light and is affine in
// the image over a plane (−depth for an orthographic view, 1/z for a perspective one), so
// that a triangle is drawn by evaluating one affine function; the largest is kept.
class DepthMap {
 public:
  DepthMap(int nx, int ny)
      : nx_(nx), ny_(ny), nearness_(static_cast<std::size_t>(nx) * ny, kEmpty) {}

  // Empties it at nx × ny texels, in the storage it has where that is enough.
  void reset(int nx, int ny) {
    nx_ = nx;
    ny_ = ny;
    nearness_.assign(static_cast<std::size_t>(nx) * ny, kEmpty);
  }

  int width() const { return nx_; }
  int height() const { return ny_; }
  float at(int i, int j) const { return nearness_[static_cast<std::size_t>(j) * nx_ + i]; }

  // Covers the texels whose centres (i + 0.5, j + 0.5) lie in the convex polygon `poly`
  // (texel coordinates, edges included, `box` its box) with nearness a·x + b·y + c.
  void draw(std::span<const glm::dvec2> poly, const TexelBox& box, double a, double b, double c);

 private:
  static int to_texel(double v, int n) { return static_cast<int>(std::clamp(v, -1.0, double(n))); }

  int nx_, ny_;
  std::vector<float> nearness_;
};

}  // namespace shadowgen::sampled::detail
