#pragma once

// The instants of a scene's `sun` lights as CSV (docs/scene-format.md, "Sun instants
// CSV"): one row per directional light a `sun` entry placed, in the scene's light order
// (each sun path's instants in time order):
//
//   light,instant,time,step_min,azimuth_deg,elevation_deg,direction_x,direction_y,direction_z
//   march21,march21@2026-03-21T06:10,2026-03-21T06:10,10,90.38...,1.03...,-0.99...,...
//
// `light` is the `sun` entry's id, `instant` the light's own id (the entry's id for a
// single `time`), `time` local standard time, `step_min` the minutes the instant stands for
// (0 for a single `time`), azimuth clockwise from true north, apparent elevation, and the
// direction the light travels in scene axes as a unit vector. Numbers with %.17g; ids
// quoted as RFC 4180 says, guarded as `ids` says. Lines end with "\n". A scene without sun
// lights is an InputError naming Scene::file (the header alone would hide a scene that was
// meant to have some); a sun path whose sun is down at every step gives the header alone.

#include <string>

#include "shadowgen/model/scene.h"
#include "shadowgen/output/report.h"

namespace shadowgen {

std::string sun_instants_csv(const Scene& scene, CsvIds ids = CsvIds::kExact);

}  // namespace shadowgen
