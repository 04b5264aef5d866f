#pragma once

// Per light, how much of it reaches the surface seen through each pixel
// (pixel_surfaces.h): a lit weight in [0, 1], found by one of six methods, the view
// methods of the methods ladder (docs/scene-format.md, "Methods"):
//
//   exact       the shadowed database's own lit polygons (ShadowedScene::lit): 1 where
//               the pixel's point lies in its face's lit region for the light, 0 elsewhere.
//               No shadow is computed. The test is made in the part's plane chart
//               (hsr/plane_chart.h, the world's own coordinates), even-odd over the loops
//               of the lit polygons on the pixel's part, half-open (a point on an edge
//               is inside for the polygon on one side of it only, as x < the edge's
//               crossing and y in [ymin, ymax) of the edge decide).
//   shadow-map  sampled::ShadowMap (shadowgen/sampled/shadow_map.h), depth maps of
//               `resolution` texels a side from each light with percentage-closer
//               filtering: a multiple of 1/9; limited by the resolution and the bias.
//   volumes     Bergeron's (1986) general shadow volumes counted along each pixel's eye
//               ray (detail/shadow_volumes.h): 1 where no volume holds the point, 0
//               where one does; any polygons (open models, triangulated non-planar ones),
//               the eye anywhere.
//   stencil     Heidmann's (1991) shadow volumes counted in the stencil buffer of a real
//               OpenGL context (stencil_shadows.h; Mesa's OSMesa on the CPU), z-pass, or
//               z-fail where the eye may be inside a volume: 1 where the stencil is 0 at
//               the pixel, 0 elsewhere. GL rasterises the scene again, so at a silhouette
//               the surface it sees can differ by a pixel from the one given here.
//               One volume per occluding polygon: open models shadow as they should.
//   stencil-silhouettes
//               the same, with the paper's volumes: extruded from silhouette edges only
//               (StencilVolumes::kSilhouettes), edges matched by identical coordinates.
//               Right on closed 2-manifold models; an open model's border is no
//               silhouette, so its shadow goes missing in part or whole (a lone polygon
//               casts none under z-pass).
//   angular     Thakur, Cheng and Miura's ridge-edge loops and discretised angular span
//               table (angular_shadows.h), `resolution` rows: 1 or 0; closed objects.
//
// What a light takes into account is the exact generator's rule (light_scope.h) for the
// sampled methods, and the database's for exact. Whatever the method, the weight is 0 for
// a pixel that sees nothing, a part seen from its back side, a part whose front side does
// not face the light (or sees it edge-on), and a part beyond a point light's range.end;
// and 0 for every light the database keeps no lit polygons for (the instants of a sun path
// summed into lit areas): the SVG picture (render.h) draws none of those either.

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "shadowgen/model/method.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/view/pixel_surfaces.h"

namespace shadowgen {

enum class PixelShadows : unsigned char {
  kExact,
  kShadowMap,
  kVolumes,
  kStencil,
  kAngular,
  kStencilSilhouettes,
};

// "exact", "shadow-map", "volumes", "stencil", "angular", "stencil-silhouettes".
std::string_view pixel_shadows_name(PixelShadows method);
// The method of that name; nullopt for any other.
std::optional<PixelShadows> pixel_shadows_named(std::string_view name);

struct PixelShadowOptions {
  PixelShadows method = PixelShadows::kExact;
  // shadow-map: texels per side; angular: rows of the span table; 1 to kMaxResolution.
  int resolution = kDefaultResolution;
};

struct PixelLitWeights {
  std::size_t lights = 0;       // scene.lights.size()
  std::vector<double> weights;  // [pixel · lights + light], pixels as PixelSurfaces orders them

  double at(std::size_t pixel, std::size_t light) const { return weights[pixel * lights + light]; }
};

// The lit weight of every pixel of `surfaces` (seen in `shadowed`'s scene) for every light.
// Throws std::invalid_argument for a resolution out of range, std::runtime_error where
// Embree fails.
PixelLitWeights pixel_lit_weights(const ShadowedScene& shadowed, const PixelSurfaces& surfaces,
                                  const PixelShadowOptions& options);

}  // namespace shadowgen
