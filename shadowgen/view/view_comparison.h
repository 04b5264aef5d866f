#pragma once

// The view methods (pixel_shadows.h) measured against the exact one from a view of the
// scene (`shadowgen compare --view`): each one's lit weights timed, and the share of
// (pixel, light) pairs off region boundaries whose lit state differs from exact's.
//
// A pair's lit state is lit where its weight is at least 1/2 (exact and volumes give 0 or
// 1, a shadow map a multiple of 1/9). Compared are the pairs of a pixel seen from its
// front, for a light whose lit polygons the database keeps (not an instant of a sun path
// summed into lit areas: every method gives those 0), and off the boundaries: a pair is
// left out where the pixel's 3 × 3 neighbourhood (clamped at the picture's edge) is not
// uniform in the face seen or in exact's lit state for that light, since there a pixel's
// state turns on where within it the boundary passes.

#include <span>

#include "shadowgen/model/method.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/view/pixel_shadows.h"
#include "shadowgen/view/pixel_surfaces.h"

namespace shadowgen {

// A lit weight's lit state: at least 1/2.
inline bool lit_state(double weight) { return weight >= 0.5; }

// `other`'s lit states against `exact`'s over the pixels of `surfaces` (both of them
// pixel_lit_weights of `shadowed` and `surfaces`), boundaries left out as above.
LitAgreement lit_agreement(const ShadowedScene& shadowed, const PixelSurfaces& surfaces,
                           const PixelLitWeights& exact, const PixelLitWeights& other);

// From `view` of `exact`'s scene (perspective, as camera_from_view makes it), width ×
// height pixels: the surfaces seen, found once; exact's lit weights, the reference; then
// each of `methods` in turn, timed and compared with it (an exact one among them takes the
// reference's time, and agrees everywhere), the Pareto-optimal ones marked (time against
// share). `exact` is an exact database (its lit polygons). Throws what pixel_surfaces and
// pixel_lit_weights throw.
ViewComparison compare_view_methods(const ShadowedScene& exact, const ViewSpec& view, int width,
                                    int height, std::span<const PixelShadowOptions> methods);

}  // namespace shadowgen
