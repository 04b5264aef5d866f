#pragma once

// A picture of the shadowed database as pixels: the surface seen through each pixel's
// centre (pixel_surfaces.h), its lit weight per light by a view method (pixel_shadows.h:
// exact, shadow-map or volumes), shaded by render.h's formula (shade_weighted: albedo,
// ambient, Lambert per light with the range fall-off, each light's term times its lit
// weight), evaluated at the pixel's own 3D point. A part seen from its back side gets the
// ambient colour; a pixel that sees nothing, the background. Colours are written as
// 8-bit round(255·v), as in the SVG picture.
//
// With the exact method the picture is the SVG picture (render.h) sampled at the pixel
// centres, but for the shading, which the SVG evaluates once per piece (at its centroid)
// and this picture per pixel: equal for directional lights, which shade a plane
// uniformly.

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/pixel_shadows.h"
#include "shadowgen/view/png_writer.h"
#include "shadowgen/view/render.h"

namespace shadowgen {

struct RasterOptions {
  RenderOptions picture;       // size, albedo, ambient, background
  PixelShadowOptions shadows;  // the view method
};

// Throws std::invalid_argument for a bad camera or size (see CameraView) or a resolution
// out of range; std::runtime_error where Embree fails.
RgbImage render_raster(const ShadowedScene& shadowed, const Camera& camera,
                       const RasterOptions& options);

}  // namespace shadowgen
