#include "bench/scenes/triangle_soup.h"

#include "bench/scenes/random.h"

namespace shadowgen::bench {

std::vector<hsr::Polygon3> triangle_soup(std::size_t count, std::uint64_t seed) {
  SceneRandom random(seed);
  std::vector<hsr::Polygon3> soup;
  soup.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3 centre(random.unit(), random.unit(), random.unit());
    const double r = random.log_uniform(0.003, 0.03);
    hsr::Polygon3 t;
    for (int v = 0; v < 3; ++v) {
      t.outer.push_back(centre + r * glm::dvec3(random.uniform(-1.0, 1.0),
                                                random.uniform(-1.0, 1.0),
                                                random.uniform(-1.0, 1.0)));
    }
    soup.push_back(std::move(t));
  }
  return soup;
}

}  // namespace shadowgen::bench
