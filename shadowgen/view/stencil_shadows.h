#pragma once

// Heidmann's stencil shadow volumes on OpenGL through Mesa's OSMesa, a raster baseline to
// set against the exact shadows per pixel: the passes per light and camera (depth, volumes
// per polygon or from silhouette edges, z-pass or z-fail, read back) and the GL camera that
// keeps a far scene precise are docs/stencil-shadows.md. It never reads a shadowed database.

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
