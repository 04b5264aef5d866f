#pragma once

// The surface seen through each pixel of a picture (a G-buffer): which face and part, the
// 3D point, the part's normal, the side seen and the depth. What the pictures made pixel
// by pixel (raster_render.h) shade, whatever finds their shadows (pixel_shadows.h).
//
// Pixel (x, y) is sampled at its centre, (x + 0.5, y + 0.5) in the camera's pixel
// coordinates (camera.h: x right, y down, (0, 0) the top-left corner), by one ray: from
// the eye through that point (perspective), or along the view from the point's foot on
// the plane through the eye perpendicular to the view (orthographic), so that what lies
// behind the eye is not seen, as in the SVG picture (render.h). A perspective ray starts
// at the camera's near distance.
//
// Which part a ray meets first is found by Intel Embree over the triangles of every part
// of every face (shadowgen/sampled/part_triangles.h), front and back, in floats, in robust
// (watertight) mode, the triangles relative to the scene's centre: so it is decided
// within the float rounding of the scene's size (2^-24 of its largest extent from its
// centre) of the exact answer, and a ray through an edge shared by two triangles of a
// part never slips between them. Every part the ray meets is then taken again in double
// precision: the point is where the double ray meets the part's own plane (hsr::plane_of),
// and the nearest such point wins.
//
// Tie rule: parts met at the same depth within 2^-40 of it (a pixel centre on an edge
// shared by two faces, coplanar overlapping faces) go to the lowest part of the lowest
// face (scene order), whatever order Embree finds them in: every picture of one scene and
// camera sees the same surfaces.

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/view/camera.h"

namespace shadowgen {

inline constexpr std::size_t kNoFace = static_cast<std::size_t>(-1);

struct PixelSurface {
  std::size_t face = kNoFace;  // index into scene.faces; kNoFace: nothing, the background
  std::size_t part = 0;        // index into the face's parts
  glm::dvec3 point{0.0};       // on the part's plane
  glm::dvec3 normal{0.0};      // the part's unit front normal (hsr::plane_of)
  bool front = false;          // the ray meets the part's front side
  double depth = 0.0;          // (point − eye)·forward, the distance along the view
  // Where the pixel's ray starts: the eye (perspective), or its foot on the plane through
  // the eye (orthographic). Set for every pixel, the background's included.
  glm::dvec3 from{0.0};

  bool seen() const { return face != kNoFace; }
};

struct PixelSurfaces {
  int width = 0;
  int height = 0;
  bool perspective = false;
  glm::dvec3 eye{0.0};
  glm::dvec3 forward{0.0, 0.0, -1.0};  // unit
  Camera camera;                       // the camera they are seen by, as given
  std::vector<PixelSurface> pixels;    // row by row from the top, each from the left

  const PixelSurface& at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
  }
};

// The surfaces of `scene` seen from `camera` in a width × height picture. Throws
// std::invalid_argument for a bad camera or size (see CameraView), std::runtime_error where
// Embree fails.
PixelSurfaces pixel_surfaces(const Scene& scene, const Camera& camera, int width, int height);

}  // namespace shadowgen
