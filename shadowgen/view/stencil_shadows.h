#pragma once

// Shadows on a raster, the way graphics hardware draws them: Heidmann's stencil shadow
// volumes ("Real shadows, real time", IRIS Universe 18, 1991; Crow's volumes, SIGGRAPH
// 1977), on OpenGL through Mesa's OSMesa, an off-screen context rendered on the CPU. The
// same calls run on a GPU's GL. A baseline to set against the exact shadows, per pixel; it
// never reads a shadowed database.
//
// Per light and camera:
//   1. the depth pass: every part of every face, triangulated (sampled/part_triangles.h),
//      into the depth buffer (24 bits); red 1 where the part faces the light
//      (shadows/light_scope.h: kFacing), 0 otherwise;
//   2. the shadow volumes: one per part that stands in the light's way (light_scope.h:
//      every role but kLeftOut, faces turned away included, as the exact generator takes
//      them), per polygon, no silhouette search: a side quad from each edge of the part's
//      outer loop and holes, extruded away from the light, and for z-fail the part's
//      triangles as the near cap and their extrusion as the far cap. Volumes of adjacent
//      parts overlap and their counts add, so open models and one-sided faces shadow as
//      they do in the exact generator; a pixel behind more than 255 parts (counted along
//      its segment to the light) wraps to 0 and reads as lit.
//      StencilVolumes::kSilhouettes builds them as the paper does instead: one volume per
//      closed object, from its silhouette edges only. Edges are matched across the
//      occluding parts (every role but kLeftOut, with a plane) by identical endpoint
//      coordinates, either way round (detail/ridge_edge_loops.h); a part is front where
//      the light is on its front side (kFacing's test, kOccluder parts included); an edge
//      with two adjacent parts, one front and one not, is a silhouette edge, extruded as
//      a side quad directed as its front part's loop runs along it (counter-clockwise
//      about the part's normal, as the per-polygon sides), and the z-fail caps are the
//      front parts and their extrusion (Everitt and Kilgard). On a closed, consistently
//      oriented (2-manifold) model the count at a point is then the number of front parts
//      on its segment to the light, and agrees with the per-polygon form. The paper
//      assumes such models: an edge with one adjacent part (an open model's border) or
//      more than two is no silhouette edge, so an open model's volume is left open or
//      missing. A lone polygon has none at all: z-pass draws nothing for it and what it
//      shadows reads lit; z-fail draws only its caps, whose count nothing closes, so the
//      polygon itself reads dark (and an open ground quad facing a sun, in perspective
//      where the far cap is not drawn, swaps lit and shadow in front of it); a part
//      turned away from the light with no front neighbour casts nothing in either;
//   3. drawn into the stencil buffer (8 bits, GL_INCR_WRAP/GL_DECR_WRAP, front and back
//      faces in two culled passes) with depth writes and colour off, the volumes pushed
//      back by glPolygonOffset(0.5, 4) so that a part is not shadowed by its own volume:
//        z-pass (Heidmann): front faces increment, back faces decrement where the depth
//          test passes; sides only. Wrong where the near plane cuts a volume (an eye in
//          shadow): that pixel's count starts inside;
//        z-fail (Carmack's reverse, Everitt and Kilgard 2002): back faces increment,
//          front faces decrement where it fails, with both caps; right wherever the eye is,
//          as long as the far plane cuts no volume;
//      kAutomatic takes z-pass only where no volume can reach the near plane within the
//      picture (the window W): a point of W is in a part's volume when its segment toward
//      the light meets the part, so z-pass is safe when no occluding part's triangle (with
//      kSilhouettes, no front part's) meets the hull of W and a point light, or of W and W
//      moved toward a directional light past the scene (a separating-axis test in doubles,
//      touching counted as meeting);
//      z-fail otherwise. An eye in shadow always gets z-fail;
//   4. read back: lit where the stencil is 0, the depth below 1 (a surface) and the red 1.
//
// GL details (stencil_gl_camera): vertices are handed to GL relative to the view's eye
// (the picture's centre, orthographic) and the modelview is a rotation, so a scene far
// from the origin keeps its precision in GL's floats. The projection reproduces
// CameraView's pixel map: pixel (x, y) of the picture, row 0 at the top, is the GL
// window's (x, height − y), pixel centres at half-integers as GL samples them.
//   Perspective: Everitt and Kilgard's infinite far plane (with 2^-20 of slack so that
//   points at infinity stay inside the depth range), volumes extruded to infinity
//   (w = 0: a point light's vertices along v − light, a directional light's to its
//   direction, whose far cap is then a point and is not drawn); the near plane fitted to
//   the scene: 0.99 × the nearest distance from the eye to a part over the frustum's
//   corner factor √(1 + tan²(fov/2)(1 + aspect²)), never below the view's own near. The
//   24-bit depth then resolves z²/(near · 2^24) at depth z.
//   Orthographic: near at the plane through StencilOptions::eye (as render cuts it), or at
//   the scene's nearest vertex; volumes extruded to finite length past the scene's
//   bounding sphere (a directional light's by a translation longer than its diameter, a
//   point light's by scaling about the light, one scale for all silhouette volumes so that
//   they close where their parts meet), and the far plane fitted to the scene and
//   the extruded vertices: a depth step of (far − near) / 2^24.

#include <array>
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/view/camera.h"

namespace shadowgen {

enum class StencilMethod : unsigned char {
  kAutomatic,  // z-pass where the eye is outside every volume, z-fail otherwise
  kZPass,      // forced, for tests: Heidmann's counting even where it fails
  kZFail,      // forced
};

enum class StencilVolumes : unsigned char {
  kPerPolygon,   // a closed volume per occluding part: open models shadow too
  kSilhouettes,  // Heidmann's: from silhouette edges only; closed 2-manifold models only
};

struct StencilOptions {
  StencilMethod method = StencilMethod::kAutomatic;
  StencilVolumes volumes = StencilVolumes::kPerPolygon;
  // Orthographic views: the camera's eye (Camera::eye), whose plane cuts the scene as
  // render does; without it the near plane is the scene's nearest vertex. Ignored for
  // perspective views.
  std::optional<glm::dvec3> eye;
};

// Per pixel, whether `light` reaches the surface seen there, found with Heidmann's stencil
// shadow volumes on OpenGL (Mesa's OSMesa, an off-screen context on the CPU; the same calls
// run on a GPU's GL). Pixel (x, y), row 0 at the top, x + y·width. 1: lit, 0: in shadow or
// no surface or the surface turned away from the light.
struct StencilResult {
  std::vector<std::uint8_t> lit;
  int width = 0, height = 0;
  bool zfail_used = false;
};

// Throws std::runtime_error when OSMesa cannot make a context with 24 depth and 8 stencil
// bits and GL 1.4 (stencil wrap), std::invalid_argument for a light without a direction.
// Each call makes its own context and leaves none current on its thread.
StencilResult stencil_lit_mask(const Scene& scene, const Light& light, const CameraView& view,
                               const StencilOptions& options = {});

// The GL transform stencil_lit_mask draws with: a vertex p is given to GL as
// (p − origin, 1); clip = projection · modelview · that (column-major, as glLoadMatrixd
// takes them); window = viewport of width × height; pixel y = height − window y.
struct StencilGlCamera {
  glm::dvec3 origin{0.0};
  std::array<double, 16> modelview{};
  std::array<double, 16> projection{};
  bool perspective = true;
  double near = 0.0;      // along the view direction from the eye (perspective) or, orthographic,
  double far = INFINITY;  // from the picture's centre; far is infinite for perspective
  bool front_ccw = true;  // glFrontFace: GL_CCW where the map keeps orientation
};
StencilGlCamera stencil_gl_camera(const Scene& scene, const Light& light, const CameraView& view,
                                  const StencilOptions& options = {});

// The silhouette edges StencilVolumes::kSilhouettes extrudes for `light`, each from a to b as
// its front part's loop runs along it: on a closed model, loops counter-clockwise seen from
// the light.
struct StencilEdge {
  glm::dvec3 a, b;
};
std::vector<StencilEdge> stencil_silhouette_edges(const Scene& scene, const Light& light);

}  // namespace shadowgen
