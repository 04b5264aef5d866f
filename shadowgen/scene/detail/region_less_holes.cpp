#include "region_less_holes.h"

#include <vector>

#include "clipper/clip.h"

namespace shadowgen::scene::detail {

clipper::PolygonSet2 region_less_holes(std::span<const clipper::Loop2> loops) {
  const clipper::PolygonWithHoles2 outer{loops[0], {}};
  std::vector<clipper::PolygonWithHoles2> holes;
  holes.reserve(loops.size() - 1);
  for (std::size_t k = 1; k < loops.size(); ++k) holes.push_back({loops[k], {}});
  return clipper::clip(outer, holes).outside;
}

}  // namespace shadowgen::scene::detail
