#pragma once

// A face part as triangles on its own vertices: what the sample points are spread over
// (face_samples.h) and what the occluders are made of (ray_caster.h, shadow_map.h). A
// part may be concave and have holes; it is triangulated by ear clipping
// (clipper/triangulate.h) in its plane's chart (hsr/plane_chart.h), and every triangle
// lies in the part's plane because the part is planar (the reader split a non-planar
// polygon into triangle parts).

#include <glm/vec3.hpp>
#include <vector>

#include "hsr/polygon3.h"

namespace shadowgen::sampled {

struct Triangle3 {
  glm::dvec3 a, b, c;
};

struct PartTriangles {
  std::vector<Triangle3> triangles;  // those with area
  // upto[k]: the areas of triangles[0, k) summed; upto.back() their whole area.
  std::vector<double> upto{0.0};
  double area = 0.0;       // the part's area as hsr::area gives it: what its estimate scales
  glm::dvec3 normal{0.0};  // hsr::plane_of's unit normal (front side); zero without a plane
  double magnitude = 0.0;  // the largest |coordinate| of its vertices

  double triangle_area() const { return upto.back(); }
};

// Throws std::runtime_error where a part with a plane cannot be triangulated (valid
// input, as the scene reader accepts it, always can). A part without area gives none.
PartTriangles part_triangles(const hsr::Polygon3& part);

}  // namespace shadowgen::sampled
