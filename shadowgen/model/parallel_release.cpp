#include "shadowgen/model/parallel_release.h"

#include "hsr/parallel.h"

namespace shadowgen {

void release_faces_in_parallel(ShadowedScene& shadowed) {
  const LitTable& lit = shadowed.lit();  // one row per face (ShadowedScene's rule)
  const std::size_t lights = lit.lights();
  hsr::for_each_in_parallel(shadowed.scene().faces.size(), [&](std::size_t f) {
    shadowed.edit_face(f, [](Face& face) { face = Face(); });
    for (std::size_t l = 0; l < lights; ++l) {
      if (lit.kept(l)) shadowed.lit_at(f, l) = LitTable::Polygons();
    }
  });
}

}  // namespace shadowgen
