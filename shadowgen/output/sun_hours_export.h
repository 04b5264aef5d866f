#pragma once

// Wavefront OBJ + MTL output of one sun path's sun-hours regions (docs/scene-format.md,
// "Sun-hours maps"): every face's regions grouped by band of hours (hour_bands.h), one
// material per band in the ramp's colour, so any OBJ viewer shows the map. Made from the
// shadowed database alone, as the OBJ export by light set is (obj_export.h), and laid out
// as it is, but for the groups:
//
//   # shadowgen OBJ export: sun hours of sun path 'march21', by band
//   mtllib scene.mtl
//   v x y z                      a face's vertices, then its normals (vn), as obj_export.h
//   g <face id>@<band name>      one group per band the face has regions in, bands in order
//   usemtl <band name>
//   f a//n b//n c//n             the triangles of the face's regions in that band
//
// Group names are obj_name(face id + "@" + band name) ("the ground@2-4h" is
// "the%20ground@2-4h"): band names ("0-2h", "10h+") hold no '@', so the face id is what
// comes before the last '@' once the escapes are undone. A face without regions (a face
// without area) gets the empty group of the first band, so that every face is named.
//
// The MTL has one material per band, even a band no region falls in, named obj_name(band
// name), its Ka and Kd the band's colour (sRGB, hour_bands.h), Ks 0 0 0, d 1, illum 1; a
// comment above each gives the band's label.

#include <string_view>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/hour_bands.h"
#include "shadowgen/output/obj_export.h"

namespace shadowgen {

// Both texts; `mtl_file_name` as in obj_export. `path` is one of shadowed.sun_paths, its
// regions shaped [face] (std::invalid_argument otherwise), `bands` its hour bands. Throws
// GenerationError naming the face should a region fail to triangulate (valid regions do
// not).
ObjFiles sun_hours_obj_export(const ShadowedScene& shadowed, const SunPathHours& path,
                              const HourBands& bands, std::string_view mtl_file_name);

}  // namespace shadowgen
