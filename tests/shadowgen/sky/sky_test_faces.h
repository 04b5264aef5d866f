#pragma once

// Faces the sky's tests build by hand.

#include <glm/vec3.hpp>
#include <string>
#include <utility>

#include "shadowgen/model/scene.h"

namespace shadowgen::test {

// A face of one part without holes, the quadrilateral a, b, c, d (its front seen with them
// counterclockwise).
inline Face quad(std::string id, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
  Face face;
  face.id = std::move(id);
  face.parts.push_back({{a, b, c, d}, {}});
  return face;
}

}  // namespace shadowgen::test
