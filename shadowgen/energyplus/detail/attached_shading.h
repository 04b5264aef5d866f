#pragma once

// Shading:Overhang and Shading:Fin (and their :Projection forms) placed from their window
// or door, as SurfaceGeometry.cc's GetSimpleShdSurfaceData places them: the opening's
// lower left corner (its vertex 2) taken into its base surface's plane, the overhang
// `Height above Window or Door` over the opening's top, `Left extension` to the left of
// it, tilted from the opening by `Tilt Angle from Window/Door`; each fin beside the
// opening's side (`Left`/`Right Extension from Window/Door`), from `Distance Below
// Bottom` under it to `Distance Above Top` over it, turned from the opening's azimuth by
// its tilt. A :Projection object gives its depth as a fraction of the opening's height
// (overhang) or width (fin).

#include <array>
#include <optional>

#include "detail/object_fields.h"
#include "detail/placement.h"

namespace shadowgen::energyplus::detail {

// The overhang; nullopt when its length times its depth is not positive (EnergyPlus then
// enters no surface).
std::optional<PlacedSurface> place_overhang(const ObjectFields& overhang,
                                            const PlacedSurface& opening,
                                            const PlacedSurface& base);

// The left and the right fin, EnergyPlus's `<Name> Left` and `<Name> Right`; each nullopt
// when its length times its depth is not positive.
std::array<std::optional<PlacedSurface>, 2> place_fins(const ObjectFields& fin,
                                                       const PlacedSurface& opening,
                                                       const PlacedSurface& base);

}  // namespace shadowgen::energyplus::detail
