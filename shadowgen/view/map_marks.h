#pragma once

// The marks that make a picture a map: a north arrow and a scale bar (render.h's
// NorthArrow and ScaleBar; svg_writer.h draws them).
//
// North: the database's site says where true north lies in the scene (Site::north_axis_deg:
// the scene's +y is that many degrees clockwise from true north, seen from above), so true
// north is the horizontal direction n = (−sin a, cos a, 0). The arrow is n's image at the
// camera's target: for an orthographic camera the image of n itself, for a perspective
// one that of the segment from the target to target + d·n, d a 1/1024 of the distance
// from the eye to the target. Its angle is measured clockwise from the picture's up. A
// view in which north does not show (its image shorter than 1/1024 of what it would be
// seen face-on: looking along north, or nearly) has no arrow, and neither has a database
// without a site, whose north is unknown.
//
// Scale: in orthographic views only (a perspective picture has no one scale), the longest
// round length, 1, 2 or 5 × 10^k scene units, whose bar is at most a quarter of the
// picture's width. A scene with a site is in metres (sun paths and geographic coordinates
// are), and its bar says "m"; any other says "units".

#include <optional>

#include "shadowgen/model/scene.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/render.h"

namespace shadowgen {

std::optional<NorthArrow> north_arrow(const Scene& scene, const Camera& camera,
                                      const CameraView& view);

// Needs pixels_per_unit > 0 and width >= 1.
ScaleBar scale_bar(double pixels_per_unit, int width, bool metres);

}  // namespace shadowgen
