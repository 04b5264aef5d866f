#pragma once

// The cameras and picture sizes that the tests of pictures (render, sun-hours maps) share.

#include <glm/vec3.hpp>

#include "shadowgen/view/camera.h"
#include "shadowgen/view/render.h"

namespace shadowgen::test {

// An orthographic camera at `eye` looking at `target` below it, world +y up in the
// picture; pixels_per_unit 0 fits the scene into the picture.
inline Camera looking_down(const glm::dvec3& eye, const glm::dvec3& target,
                           double pixels_per_unit) {
  Camera camera;
  camera.eye = eye;
  camera.target = target;
  camera.up = {0, 1, 0};
  camera.orthographic = true;
  camera.pixels_per_unit = pixels_per_unit;
  return camera;
}

// Options for a picture of width × height pixels, the rest as default.
inline RenderOptions picture_size(int width, int height) {
  RenderOptions options;
  options.width = width;
  options.height = height;
  return options;
}

}  // namespace shadowgen::test
