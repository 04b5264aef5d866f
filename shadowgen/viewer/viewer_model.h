#pragma once

// What the viewer page (`shadowgen view`, viewer_page.h) shows of a shadowed database: the
// faces split by the set of lights reaching them (shadowgen/shadows/light_regions.h), or
// by one sun path's bands of sun hours (shadowgen/output/hour_bands.h), as a binary glTF
// 2.0 model, and beside it what the page's legend, toggles and hover box say.
//
// The model (GLB), made from the database alone:
//   - one mesh per group that has pieces (a light set, or a band of hours), groups in
//     legend order (light sets in LightSetLess order; bands in increasing hours), each one
//     primitive of triangles: POSITION (float32) and _FACE (float32, the index of the face
//     in the database's order, exact below 2^24 faces), with a material named after the
//     group in its colour (KHR_materials_unlit, baseColorFactor the colour in linear sRGB);
//   - one mesh of lines, the outlines of every face's parts (holes included);
//   - one node per mesh, translated to the origin (below); the node's extras hold
//     {"group": k} (k the index in the page's groups) or {"outline": true}.
// Positions are the scene's coordinates less the origin, mapped from the scene's +z up to
// glTF's +y up: (x, y, z) -> (x, z, -y), rounded once to float32. The origin is the
// centre of the faces' bounding box, so a district at projected coordinates of 1e6 keeps
// its vertices to float32's rounding of the district's own size. Each piece is triangulated
// on its own vertices in its part's plane (shadowgen/sampled/part_triangles.h), written
// once; the page shows both sides.
//
// The page's description (JSON): title (the input's file name), caption (lines above the legend),
// groups (name, label, colour in sRGB, and for a light set the indices of its lights in `lights`,
// or for a band its hours from and to), lights (the lights some light set holds: id, intensity),
// total_intensity (of every light of the scene, over which the colour rule of obj_export.h
// divides), faces (id, area, and per light in `lights` the lit area; or the area-weighted mean sun
// hours), origin, the scene's views, and north_axis_deg: the site's, or else what a sun
// light's azimuth and direction give (a database keeps no site), where either is known.

#include <string>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/hour_bands.h"

namespace shadowgen {

struct ViewerModel {
  std::string glb;          // the binary glTF, as bytes
  std::string description;  // the page's description, JSON
};

// The faces split by light sets. Throws std::invalid_argument when `lit` is not shaped
// [face][light], GenerationError naming the face where a region fails to triangulate.
ViewerModel viewer_model(const ShadowedScene& shadowed);

// One sun path's sun-hours regions by band: `path` one of shadowed.sun_paths, with its
// regions, `bands` its hour bands (std::invalid_argument otherwise).
ViewerModel viewer_model(const ShadowedScene& shadowed, const SunPathHours& path,
                         const HourBands& bands);

// model.js: the script that hands the page its model, without any file being fetched
// (a page opened from the file system may not fetch one):
//   window.shadowgenModel = {"meta": <description>, "glb": "<GLB in base64>"};
std::string viewer_model_script(const ViewerModel& model);

}  // namespace shadowgen
