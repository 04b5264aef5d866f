#pragma once

// The shadowed database in memory: the scene plus, for every (face, light), the lit detail
// polygons, in the face's own plane and the scene's coordinates (the paper's "lighted
// details attached to parent polygons"). Everything later output needs comes from it.

#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen {

struct ShadowedScene {
  Scene scene;
  // lit[face][light]: polygons with holes covering exactly the lit region; empty when
  // unlit.
  std::vector<std::vector<std::vector<hsr::Polygon3>>> lit;
};

}  // namespace shadowgen
