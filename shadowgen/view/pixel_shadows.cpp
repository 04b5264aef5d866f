#include "shadowgen/view/pixel_shadows.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

#include "detail/shadow_volumes.h"
#include "hsr/parallel.h"
#include "hsr/plane_chart.h"
#include "shadowgen/sampled/part_triangles.h"
#include "shadowgen/sampled/shadow_map.h"
#include "shadowgen/shadows/light_scope.h"
#include "shadowgen/view/angular_shadows.h"
#include "shadowgen/view/stencil_shadows.h"

namespace shadowgen {
namespace {

// The scene's parts (light_scope.h), found by the pixel that sees one.
struct SceneParts : ScenePartPlanes {
  using ScenePartPlanes::index;
  using ScenePartPlanes::ScenePartPlanes;
  std::size_t index(const PixelSurface& pixel) const { return index(pixel.face, pixel.part); }
};

// Whether the light's weight can be other than 0 at the pixel: a part seen from its front,
// facing the light (role kFacing).
bool may_be_lit(const PixelSurface& pixel, const SceneParts& parts,
                const std::vector<PartRole>& roles) {
  return pixel.seen() && pixel.front && roles[parts.index(pixel)] == PartRole::kFacing;
}

// Calls work(pixel index) for every pixel, rows in parallel.
template <typename Work>
void for_each_pixel(const PixelSurfaces& surfaces, Work&& work) {
  const auto width = static_cast<std::size_t>(surfaces.width);
  hsr::for_each_in_parallel(static_cast<std::size_t>(surfaces.height), [&](std::size_t y) {
    for (std::size_t x = 0; x < width; ++x) work(y * width + x);
  });
}

// The lit polygons of one (face, light), flattened in the chart of their part's plane.
struct FlatLit {
  std::size_t part = 0;
  hsr::PlaneChart chart;
  std::vector<clipper::Loop2> loops;
};

// Even-odd, half-open: an edge counts where it spans y in [ymin, ymax) and passes right of
// the point.
bool inside_loops(const std::vector<clipper::Loop2>& loops, const clipper::Point2& p) {
  bool inside = false;
  for (const clipper::Loop2& loop : loops) {
    for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
      const clipper::Point2& a = loop[i];
      const clipper::Point2& b = loop[(i + 1) % n];
      if ((a.y > p.y) == (b.y > p.y)) continue;
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

void exact_weights(const ShadowedScene& shadowed, const PixelSurfaces& surfaces,
                   const std::vector<bool>& drawn, PixelLitWeights& out) {
  const Scene& scene = shadowed.scene();
  const std::size_t lights = scene.lights.size();
  // The lit polygons of the faces seen, per (face, light) and part.
  std::vector<bool> seen(scene.faces.size(), false);
  for (const PixelSurface& pixel : surfaces.pixels) {
    if (pixel.seen() && pixel.front) seen[pixel.face] = true;
  }
  std::vector<std::vector<FlatLit>> flat(scene.faces.size() * lights);
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    if (!seen[f]) continue;
    for (std::size_t l = 0; l < lights; ++l) {
      if (!drawn[l]) continue;
      for (const LitPolygon& lit : shadowed.lit().at(f, l)) {
        const hsr::Polygon3& part = scene.faces[f].parts.at(lit.part);
        FlatLit entry;
        entry.part = lit.part;
        entry.chart = hsr::chart_facing(hsr::plane_of(part).normal);
        entry.loops.push_back(entry.chart.flatten(lit.polygon.outer));
        for (const hsr::Loop3& hole : lit.polygon.holes) {
          entry.loops.push_back(entry.chart.flatten(hole));
        }
        flat[f * lights + l].push_back(std::move(entry));
      }
    }
  }
  for_each_pixel(surfaces, [&](std::size_t i) {
    const PixelSurface& pixel = surfaces.pixels[i];
    if (!pixel.seen() || !pixel.front) return;
    for (std::size_t l = 0; l < lights; ++l) {
      // The lit polygons of one part do not overlap: inside one is inside the lit region.
      for (const FlatLit& lit : flat[pixel.face * lights + l]) {
        if (lit.part == pixel.part && inside_loops(lit.loops, lit.chart(pixel.point))) {
          out.weights[i * lights + l] = 1.0;
          break;
        }
      }
    }
  });
}

std::vector<sampled::Triangle3> occluders(const SceneParts& parts,
                                          const std::vector<PartRole>& roles) {
  std::vector<sampled::Triangle3> triangles;
  for (std::size_t i = 0; i < parts.polygons.size(); ++i) {
    if (!occludes(roles[i])) continue;
    const sampled::PartTriangles part = sampled::part_triangles(parts.polygons[i]);
    triangles.insert(triangles.end(), part.triangles.begin(), part.triangles.end());
  }
  return triangles;
}

void shadow_map_weights(const Scene& scene, const PixelSurfaces& surfaces,
                        const std::vector<bool>& drawn, int resolution, PixelLitWeights& out) {
  const SceneParts parts(scene);
  const std::size_t lights = scene.lights.size();
  for (std::size_t l = 0; l < lights; ++l) {
    if (!drawn[l]) continue;
    const std::vector<PartRole> roles = part_roles(parts.polygons, parts.planes, scene.lights[l]);
    const sampled::ShadowMap map(scene.lights[l], occluders(parts, roles), resolution);
    for_each_pixel(surfaces, [&](std::size_t i) {
      const PixelSurface& pixel = surfaces.pixels[i];
      if (!may_be_lit(pixel, parts, roles)) return;
      out.weights[i * lights + l] = map.lit(pixel.point, pixel.normal);
    });
  }
}

void volume_weights(const Scene& scene, const PixelSurfaces& surfaces,
                    const std::vector<bool>& drawn, PixelLitWeights& out) {
  const SceneParts parts(scene);
  const std::size_t lights = scene.lights.size();
  // Every part and every ray's start.
  view::detail::Reach reach{glm::dvec3(std::numeric_limits<double>::infinity()),
                            glm::dvec3(-std::numeric_limits<double>::infinity())};
  auto add = [&](const glm::dvec3& p) {
    reach.lo = glm::min(reach.lo, p);
    reach.hi = glm::max(reach.hi, p);
  };
  for (const hsr::Polygon3& polygon : parts.polygons) {
    for (const glm::dvec3& p : polygon.outer) add(p);
  }
  for (const PixelSurface& pixel : surfaces.pixels) add(pixel.from);
  if (!(reach.lo.x <= reach.hi.x)) return;
  for (std::size_t l = 0; l < lights; ++l) {
    if (!drawn[l]) continue;
    const Light& light = scene.lights[l];
    const std::vector<PartRole> roles = part_roles(parts.polygons, parts.planes, light);
    const view::detail::ShadowVolumes volumes(light, parts.polygons, parts.planes, roles, reach);
    // Bergeron's eye in shadow: once for a perspective camera's one eye.
    std::vector<std::size_t> eye_holding;
    if (surfaces.perspective) eye_holding = volumes.holding(surfaces.eye);
    for_each_pixel(surfaces, [&](std::size_t i) {
      const PixelSurface& pixel = surfaces.pixels[i];
      if (!may_be_lit(pixel, parts, roles)) return;
      const std::vector<std::size_t> holding =
          surfaces.perspective ? std::vector<std::size_t>() : volumes.holding(pixel.from);
      const int count = volumes.count(pixel.from, surfaces.perspective ? eye_holding : holding,
                                      pixel.point, pixel.normal, parts.index(pixel));
      out.weights[i * lights + l] = count > 0 ? 0.0 : 1.0;
    });
  }
}

void stencil_weights(const Scene& scene, const PixelSurfaces& surfaces,
                     const std::vector<bool>& drawn, StencilVolumes volumes, PixelLitWeights& out) {
  const SceneParts parts(scene);
  const std::size_t lights = scene.lights.size();
  const CameraView view(surfaces.camera, scene, surfaces.width, surfaces.height);
  StencilOptions stencil;
  stencil.volumes = volumes;
  if (surfaces.camera.orthographic) stencil.eye = surfaces.camera.eye;
  for (std::size_t l = 0; l < lights; ++l) {
    if (!drawn[l]) continue;
    const std::vector<PartRole> roles = part_roles(parts.polygons, parts.planes, scene.lights[l]);
    const StencilResult mask = stencil_lit_mask(scene, scene.lights[l], view, stencil);
    for_each_pixel(surfaces, [&](std::size_t i) {
      if (!may_be_lit(surfaces.pixels[i], parts, roles)) return;
      out.weights[i * lights + l] = mask.lit[i] != 0 ? 1.0 : 0.0;
    });
  }
}

void angular_weights(const Scene& scene, const PixelSurfaces& surfaces,
                     const std::vector<bool>& drawn, int rows, PixelLitWeights& out) {
  const std::size_t lights = scene.lights.size();
  for (std::size_t l = 0; l < lights; ++l) {
    if (!drawn[l]) continue;
    const std::vector<double> lit = angular_lit_weights(scene, scene.lights[l], surfaces, rows);
    for (std::size_t i = 0; i < lit.size(); ++i) out.weights[i * lights + l] = lit[i];
  }
}

void check_resolution(int resolution) {
  if (resolution < 1 || resolution > kMaxResolution) {
    throw std::invalid_argument("pixel_lit_weights: the resolution must be 1 to " +
                                std::to_string(kMaxResolution) + ", not " +
                                std::to_string(resolution));
  }
}

}  // namespace

std::string_view pixel_shadows_name(PixelShadows method) {
  switch (method) {
    case PixelShadows::kExact:
      return "exact";
    case PixelShadows::kShadowMap:
      return "shadow-map";
    case PixelShadows::kVolumes:
      return "volumes";
    case PixelShadows::kStencil:
      return "stencil";
    case PixelShadows::kAngular:
      return "angular";
    case PixelShadows::kStencilSilhouettes:
      return "stencil-silhouettes";
  }
  return "exact";
}

std::optional<PixelShadows> pixel_shadows_named(std::string_view name) {
  for (const PixelShadows method :
       {PixelShadows::kExact, PixelShadows::kShadowMap, PixelShadows::kVolumes,
        PixelShadows::kStencil, PixelShadows::kAngular, PixelShadows::kStencilSilhouettes}) {
    if (pixel_shadows_name(method) == name) return method;
  }
  return std::nullopt;
}

PixelLitWeights pixel_lit_weights(const ShadowedScene& shadowed, const PixelSurfaces& surfaces,
                                  const PixelShadowOptions& options) {
  const Scene& scene = shadowed.scene();
  PixelLitWeights out;
  out.lights = scene.lights.size();
  out.weights.assign(surfaces.pixels.size() * out.lights, 0.0);
  std::vector<bool> drawn(out.lights);
  for (std::size_t l = 0; l < out.lights; ++l) drawn[l] = shadowed.lit().kept(l);
  switch (options.method) {
    case PixelShadows::kExact:
      exact_weights(shadowed, surfaces, drawn, out);
      break;
    case PixelShadows::kShadowMap:
      check_resolution(options.resolution);
      shadow_map_weights(scene, surfaces, drawn, options.resolution, out);
      break;
    case PixelShadows::kVolumes:
      volume_weights(scene, surfaces, drawn, out);
      break;
    case PixelShadows::kStencil:
      stencil_weights(scene, surfaces, drawn, StencilVolumes::kPerPolygon, out);
      break;
    case PixelShadows::kStencilSilhouettes:
      stencil_weights(scene, surfaces, drawn, StencilVolumes::kSilhouettes, out);
      break;
    case PixelShadows::kAngular:
      check_resolution(options.resolution);
      angular_weights(scene, surfaces, drawn, options.resolution, out);
      break;
  }
  return out;
}

}  // namespace shadowgen
