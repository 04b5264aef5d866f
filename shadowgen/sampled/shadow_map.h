#pragma once

// Depth maps rendered from a light (Williams 1978), looked up with 3×3 percentage-closer
// filtering (Reeves, Salesin and Cook 1987), with a receiver-plane depth bias clamped at
// kPlaneReachTexels and, for faces too small in the whole map, maps of their own (adaptive
// shadow maps). The views, the lookup and its bias, and the faces' own maps are
// docs/shadow-maps.md.

#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/sampled/part_triangles.h"

namespace shadowgen::sampled {

// The constant part of the depth bias, in texel widths at the tap's depth.
inline constexpr double kDepthBiasTexels = 0.5;
// How far behind the sample (away from the light) its plane is followed to a tap, in
// texel widths at the sample's depth: the slope clamp of the receiver-plane bias.
inline constexpr double kPlaneReachTexels = 1.0;
// How far each map reaches past what it must show, in texels.
inline constexpr double kMarginTexels = 2.0;

// The texels a face's image gets at least along each side of its box in the map a face's
// samples are looked up in (lit_face): 1/64 of the resolution, and at least 4.
constexpr double face_texels(int resolution) {
  return resolution / 64.0 > 4.0 ? resolution / 64.0 : 4.0;
}

class ShadowMap {
 public:
  // Renders the maps of `light` over `occluders`; resolution ≥ 1.
  ShadowMap(const Light& light, std::span<const Triangle3> occluders, int resolution);
  ~ShadowMap();
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;

  // The lit fraction in [0, 1] (a multiple of 1/9) of `point`, on a part whose unit front
  // normal is `normal` and whose front side the light reaches. Safe to call from several
  // threads at once.
  double lit(const glm::dvec3& point, const glm::dvec3& normal) const;

  // The lit fractions of `points` (unit front normals `normals`) on one face whose parts
  // facing the light are the triangles `face`, into `out` (as many as the points): looked
  // up in a map of the face's own where the whole map shows it with fewer than
  // face_texels(resolution) texels along a side, else as lit() does. Safe to call from
  // several threads at once.
  void lit_face(std::span<const Triangle3> face, std::span<const glm::dvec3> points,
                std::span<const glm::dvec3> normals, std::span<double> out) const;

 private:
  struct View;
  struct Tiles;
  // The view (cube face of a point light's) that holds `point`.
  int view_of(const glm::dvec3& point) const;
  // lit() in that view; `own` as View::lit sets it (shadow_map.cpp).
  double whole_lit(const glm::dvec3& point, const glm::dvec3& normal, bool* own) const;

  std::vector<Triangle3> occluders_;
  // A point light's: per occluder, the cone from the light that holds it (sin_alpha < 0:
  // every way).
  struct Cone {
    glm::dvec3 axis{0.0};
    double cos_alpha = -1.0, sin_alpha = -1.0;
  };
  std::vector<Cone> cones_;
  int resolution_ = 1;
  std::unique_ptr<View[]> views_;
  std::unique_ptr<Tiles[]> tiles_;
  int view_count_ = 0;
  bool perspective_ = false;
  glm::dvec3 eye_{0.0};
  double near_ = 0.0;  // a perspective view's near distance
};

}  // namespace shadowgen::sampled
