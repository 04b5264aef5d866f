#pragma once

// A radiation map (docs/radiation.md, "Radiation maps"): the picture render.h draws, with
// hidden surfaces removed from the eye on the parent faces only, but each visible face
// drawn whole in the colour of the band (radiation_bands.h) of its total irradiation over
// one sun path, in kWh/m² (the radiation report's total_wh_per_area / 1000), and a legend
// of the bands beside it. A face seen from its back side is drawn as 0 kWh/m², with
// `back_side` set: the report's irradiation falls on the front side, as lit regions do.
//
// Pieces carry their face's value (Piece::kwh_per_m2) and band label, and no light set.

#include <span>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/radiation_bands.h"
#include "shadowgen/view/render.h"

namespace shadowgen {

// `kwh_per_m2` holds one value per face of shadowed.scene() (std::invalid_argument
// otherwise, as for a bad camera or size); `bands` the bands they are coloured by.
Picture render_radiation(const ShadowedScene& shadowed, std::span<const double> kwh_per_m2,
                         const RadiationBands& bands, const Camera& camera,
                         const RenderOptions& options = {});

}  // namespace shadowgen
