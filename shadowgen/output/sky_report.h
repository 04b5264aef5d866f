#pragma once

// Sky view factor report (docs/sky.md, "Sky view factor report"): per face, the isotropic
// sky's view factor with exact obstruction and the face's view of the ground
// (sky/sky_exposure.h).

#include <string>

#include "shadowgen/model/scene.h"
#include "shadowgen/output/report.h"
#include "shadowgen/sky/sky_exposure.h"

namespace shadowgen {

// CSV: face_id,area,sky_view_factor,ground_view_factor, one row per face in scene order;
// numbers as the report CSV writes them, ids as CsvIds says. `exposure` is `scene`'s.
std::string sky_view_factor_csv(const Scene& scene, const sky::SkyExposure& exposure,
                                CsvIds ids = CsvIds::kExact);

}  // namespace shadowgen
