#pragma once

// Every part of every face of a scene in one list: what hidden-surface removal from each
// light works on.

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::shadows::detail {

// Where a part of the list comes from.
struct PartOwner {
  std::size_t face = 0;  // index in Scene::faces
  std::size_t part = 0;  // index among that face's parts (Face::parts, LitPolygon::part)
};

// Per part, in parallel: hidden-surface removal and the light views take the polygons and
// planes as spans.
struct FaceParts {
  std::vector<hsr::Polygon3> polygons;
  std::vector<hsr::Plane3> planes;
  std::vector<double> areas;  // hsr::area of each polygon, once for every light
  std::vector<PartOwner> owners;
  std::vector<int> coplanar;  // coplanar_groups.h: a group index, or -1
  std::size_t face_count = 0;
  glm::dvec3 centre{0.0};  // the parts' box's point nearest the origin: directional views' centre

  std::size_t size() const { return polygons.size(); }
};

// The parts of the scene's faces, face by face, each face's in order.
FaceParts flatten(const Scene& scene);

// Whether the light reaches the front side of this plane at all. A light in the plane (or
// parallel to it) leaves it unlit, as the spec settles.
bool faces_light(const hsr::Plane3& plane, const Light& light);

}  // namespace shadowgen::shadows::detail
