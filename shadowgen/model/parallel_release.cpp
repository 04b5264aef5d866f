#include "shadowgen/model/parallel_release.h"

#include "hsr/parallel.h"

namespace shadowgen {

void release_faces_in_parallel(ShadowedScene& shadowed) {
  std::vector<Face>& faces = shadowed.scene.faces;
  LitTable& lit = shadowed.lit;
  const std::size_t lights = lit.lights();
  hsr::for_each_in_parallel(faces.size(), [&](std::size_t f) {
    faces[f] = Face();
    if (f >= lit.size()) return;
    for (std::size_t l = 0; l < lights; ++l) {
      if (lit.kept(l)) lit.at(f, l) = LitTable::Polygons();
    }
  });
}

}  // namespace shadowgen
