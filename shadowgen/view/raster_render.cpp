#include "shadowgen/view/raster_render.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "hsr/parallel.h"
#include "shadowgen/view/pixel_surfaces.h"

namespace shadowgen {
namespace {

std::uint8_t byte_of(double v) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
}

void put(std::uint8_t* out, const Rgb& colour) {
  out[0] = byte_of(colour.r);
  out[1] = byte_of(colour.g);
  out[2] = byte_of(colour.b);
}

}  // namespace

RgbImage render_raster(const ShadowedScene& shadowed, const Camera& camera,
                       const RasterOptions& options) {
  const Scene& scene = shadowed.scene();
  const RenderOptions& picture = options.picture;
  const PixelSurfaces surfaces = pixel_surfaces(scene, camera, picture.width, picture.height);
  const PixelLitWeights lit = pixel_lit_weights(shadowed, surfaces, options.shadows);

  RgbImage image;
  image.width = picture.width;
  image.height = picture.height;
  image.rgb.resize(3 * surfaces.pixels.size());
  const std::vector<double> none(lit.lights, 0.0);
  hsr::for_each_in_parallel(surfaces.pixels.size(), [&](std::size_t i) {
    const PixelSurface& pixel = surfaces.pixels[i];
    std::uint8_t* out = image.rgb.data() + 3 * i;
    if (!pixel.seen()) {
      put(out, picture.background);
      return;
    }
    // A back side gets the ambient colour: its weights are all 0.
    const std::span<const double> weights =
        pixel.front ? std::span<const double>(lit.weights.data() + i * lit.lights, lit.lights)
                    : std::span<const double>(none);
    put(out, shade_weighted(scene, weights, pixel.point, pixel.normal, picture));
  });
  return image;
}

}  // namespace shadowgen
