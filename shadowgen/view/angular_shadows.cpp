#include "shadowgen/view/angular_shadows.h"

#include <glm/common.hpp>
#include <limits>
#include <stdexcept>
#include <string>

#include "detail/angular_frame.h"
#include "detail/angular_span_table.h"
#include "detail/ridge_edge_loops.h"
#include "hsr/parallel.h"
#include "shadowgen/shadows/light_scope.h"

namespace shadowgen {

std::vector<double> angular_lit_weights(const Scene& scene, const Light& light,
                                        const PixelSurfaces& surfaces, int resolution) {
  if (resolution < 1) {
    throw std::invalid_argument("angular shadows: resolution " + std::to_string(resolution) +
                                " is below 1");
  }
  std::vector<double> weights(surfaces.pixels.size(), 0.0);
  const ScenePartPlanes parts(scene);
  const std::vector<PartRole> roles = part_roles(parts.polygons, parts.planes, light);
  const view::detail::RidgeEdgeLoops loops =
      view::detail::ridge_edge_loops(parts.polygons, parts.planes, roles, light);

  // The point light's axis aims at the centre of what it takes into account.
  glm::dvec3 lo(std::numeric_limits<double>::infinity());
  glm::dvec3 hi(-std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < parts.polygons.size(); ++i) {
    if (loops.facing[i] == view::detail::Facing::kLeftOut) continue;
    for (const glm::dvec3& p : parts.polygons[i].outer) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  const glm::dvec3 centre = lo.x <= hi.x ? 0.5 * (lo + hi) : glm::dvec3(0.0);
  const view::detail::AngularFrame frame(light, centre);
  std::vector<view::detail::AngularSpanTable> tables;
  for (int h = 0; h < frame.hemispheres(); ++h) {
    tables.emplace_back(frame, h == 0 ? 1 : -1, loops, parts.polygons, resolution);
  }

  const auto width = static_cast<std::size_t>(surfaces.width);
  hsr::for_each_in_parallel(static_cast<std::size_t>(surfaces.height), [&](std::size_t y) {
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t i = y * width + x;
      const PixelSurface& pixel = surfaces.pixels[i];
      if (!pixel.seen() || !pixel.front) continue;
      if (roles[parts.index(pixel.face, pixel.part)] != PartRole::kFacing) continue;
      const int hemisphere = frame.hemisphere_of(pixel.point);
      const view::detail::AngularSpanTable& table = tables[hemisphere == 1 ? 0 : 1];
      weights[i] = table.in_shadow(frame.local(pixel.point, hemisphere)) ? 0.0 : 1.0;
    }
  });
  return weights;
}

}  // namespace shadowgen
