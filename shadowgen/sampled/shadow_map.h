#pragma once

// Depth maps rendered from a light (Williams 1978), looked up with 3×3 percentage-closer
// filtering (Reeves, Salesin and Cook 1987).
//
// Views: a directional light gets one orthographic map along its direction, fitted to
// the box of the occluders in its frame; a point light a cube of six 90° perspective maps
// around it (each storing 1/z, which is affine in the image), so that it may stand
// anywhere, inside the scene included. The occluders' triangles (every part the light
// takes into account, front or back, receivers included) are rasterised in software at
// `resolution` × `resolution` texels per map, a texel covered where its centre lies in a
// triangle's image (edges included), the nearest depth kept, in floats; triangles that a
// point light sees edge-on (its position in their plane) cover nothing; a triangle
// reaching behind a perspective map's eye is clipped at a near distance of 1e-9 of the
// occluders' box.
//
// Each map reaches kMarginTexels past what it must show (the occluders' box; a cube face's
// 90°, its image x/z, y/z in [−spread, spread] with spread a little over 1), so that a
// sample at its edge, at a cube map's seams included, is filtered with texels that hold
// what the light sees there, not the edge texels repeated.
//
// Lookup: the 3×3 texels around the one the sample falls in (clamped at the map's edge),
// each a tap. A tap passes where it is empty or where the sample's part, extended in its
// own plane to the tap's centre, is no farther from the light than the depth stored there
// plus a constant bias of kDepthBiasTexels texel widths (at the sample's depth) — but the
// plane is followed away from the light at most kPlaneReachTexels texel widths behind the
// sample (receiver-plane depth bias with a slope clamp, Isidoro 2006). Taking the part's
// own plane at each tap makes the part's own texels, those of every part coplanar with
// it, and those of a neighbour that rises towards the light from a convex edge pass
// whatever the slope, so a part seen at a grazing angle neither shadows itself (acne) nor
// needs a bias so large that shadows of nearby occluders leak away. The clamp is what a
// part nearly edge-on to the light needs: its image is a sliver narrower than a texel, so
// most of its taps fall beside it, and its plane, steep there, runs hundreds of texels
// behind the sample one texel away. Unclamped, every tap beyond its silhouette (the
// ground far behind it, say) failed, and a wholly lit face was estimated about half in
// shadow at every resolution; clamped, a tap fails only where something stands in front
// of the sample itself or of its plane towards the light. A tap whose ray from a point
// light misses the part's plane (beyond its horizon) counts as the plane at its farthest.
// The constant covers the floats the map stores (2^-24 of a depth, far below a texel up
// to kMaxResolution). The sample's lit weight is the fraction of its 9 taps that pass; as
// the resolution grows, the filter's footprint and the bias shrink with the texel, and
// the estimate tends to the exact one wherever a part's image is wider than a few texels.
// What it cannot see stays wrong until the texels are small enough: a part nearly edge-on
// (narrower in the image than a texel) shadowed by a neighbour folded over it, or an
// occluder nearer to it than the reach of its plane towards the light across one texel.
//
// Faces (lit_face, what the per-face estimate uses) are looked up at a resolution that
// follows the face, as adaptive shadow maps refine where a map is too coarse (Fernando,
// Fernandez, Bala and Greenberg 2001). A face's image is boxed along and across its
// principal axis; where the box spans fewer than face_texels(resolution) texels of the
// whole map along a side, and the whole map does not show the face's own plane at every
// tap of every sample point (which lights the face throughout, for certain), the face gets
// a map of its own over that box and kMarginTexels about it, with at least that many
// texels along each side (texels need not be square: a sliver nearly edge-on to the light
// is cut finely across, not along). It holds every occluder whose image reaches it, found
// through a grid of tiles over the whole map (for a point light's face that straddles a
// seam of the cube, its own view towards the face, every occluder whose bounding cone from
// the light meets the map's), but those wholly farther from the light than the face by
// more than the reach of its plane, which could only make taps pass. Each face is so seen
// with a number of texels across that grows with the resolution, however small or steep
// it is, and its error shrinks with the resolution as a large face's does. A face reaching
// nearer to a point light than the near distance keeps the whole map. The depth bias never
// falls below a few times the float's rounding of the depth stored (kFloatSlack in
// shadow_map.cpp), which a face's fine map can otherwise go beneath.

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
