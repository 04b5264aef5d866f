#pragma once

// A sun-hours map (docs/scene-format.md, "Sun-hours maps"): the picture render.h draws, but
// with each visible face split by one sun path's sun-hours regions instead of its light-set
// regions, each piece filled with the colour of the band of hours its region lies in
// (shadowgen/output/hour_bands.h), and a legend of the bands beside it.
//
// Method as render.h's, hidden surfaces removed from the eye on the parent faces only:
// every visible fragment of a face seen from its front side is clipped by the images of
// the face's regions in turn, all but the one of largest area, which gets what the others
// leave; so the pieces of a fragment never overlap and cover it. A face seen from its
// back side is drawn as 0 hours, one piece per visible fragment with `back_side` set: the
// regions lie on the front side, as lit regions do, and nothing reaches the back.
//
// Pieces carry their region's hours (Piece::sun_hours) and no light set; the picture's
// legend has the bands' colours and labels, and the bands' caption (HourBands::caption).

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/hour_bands.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/render.h"

namespace shadowgen {

// `path` is one of shadowed.sun_paths, its regions shaped [face] (std::invalid_argument
// otherwise, as for a bad camera or size), `bands` its hour bands.
Picture render_sun_hours(const ShadowedScene& shadowed, const SunPathHours& path,
                         const HourBands& bands, const Camera& camera,
                         const RenderOptions& options = {});

}  // namespace shadowgen
