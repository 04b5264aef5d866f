#pragma once

// Cameras the view tests take pictures with.

#include <glm/vec3.hpp>

#include "shadowgen/view/camera.h"

namespace shadowgen::test {

// A perspective camera from `eye` toward `target`, up +z, `fov` degrees high.
inline Camera perspective(const glm::dvec3& eye, const glm::dvec3& target, double fov = 50.0) {
  Camera camera;
  camera.eye = eye;
  camera.target = target;
  camera.fov_deg = fov;
  return camera;
}

}  // namespace shadowgen::test
