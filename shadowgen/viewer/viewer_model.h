#pragma once

// What the viewer page (`shadowgen view`, viewer_page.h) shows of a shadowed database: the
// faces split by the set of lights reaching them (shadowgen/shadows/light_regions.h), or
// by one sun path's bands of sun hours (shadowgen/output/hour_bands.h), as a binary glTF
// 2.0 model, and beside it what the page's legend, toggles and hover box say.
//
// The model is the glTF export's (shadowgen/output/gltf_export.h, binary): the light sets'
// file, or the sun path's bands' (export --sun-hours), with what GltfOptions adds for the
// page: a _FACE attribute on every vertex (the index of its face in the database's order)
// and a mesh of lines, the outlines of every face's parts (holes included). Its materials
// are the page's groups, in order (light sets in LightSetLess order; bands in increasing
// hours), named alike; every axis, origin and precision rule is the export's, so a district
// at projected coordinates of 1e6 keeps its vertices to float32's rounding of the
// district's own size.
//
// The page's description (JSON): title (the input's file name), caption (lines above the legend),
// groups (the materials: name, label, colour in sRGB, and for a light set the indices of its lights
// in `lights`, or for a band its hours from and to), lights (the lights some light set holds: id,
// intensity), total_intensity (of every light of the scene, over which the colour rule of
// obj_export.h divides), faces (id, area, and per light in `lights` the lit area; or the
// area-weighted mean sun hours), origin, the scene's views, and north_axis_deg: the site's, or else
// what a sun light's azimuth and direction give (a database keeps no site), where either is known.

#include <string>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/hour_bands.h"

namespace shadowgen {

struct ViewerModel {
  std::string glb;          // the binary glTF, as bytes
  std::string description;  // the page's description, JSON
};

// The faces split by light sets. Throws as gltf_export: GenerationError naming the face
// where a region fails to triangulate.
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
