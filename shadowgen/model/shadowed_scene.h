#pragma once

// The shadowed database in memory: the scene plus, for every (face, light), the lit detail
// polygons, in the face's own plane and the scene's coordinates (the paper's "lighted
// details attached to parent polygons"). Everything later output needs comes from it.

#include <cstddef>
#include <span>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen {

// One lit detail polygon, lying in the plane of part `part` of its face (Face::parts):
// the part is known where the polygon is made, so no reader of it has to guess.
struct LitPolygon {
  std::size_t part = 0;
  hsr::Polygon3 polygon;
};

struct ShadowedScene {
  Scene scene;
  // lit[face][light]: polygons with holes covering exactly the lit region; empty when
  // unlit. The polygons of one part do not overlap.
  std::vector<std::vector<std::vector<LitPolygon>>> lit;
};

// Total area of lit detail polygons (hsr::area of each).
double lit_area(std::span<const LitPolygon> lit);

// The polygons of `lit`, whatever part they lie on.
std::vector<hsr::Polygon3> polygons_of(std::span<const LitPolygon> lit);

// The polygons of `lit` that lie on part `part`.
std::vector<hsr::Polygon3> polygons_on_part(std::span<const LitPolygon> lit, std::size_t part);

}  // namespace shadowgen
