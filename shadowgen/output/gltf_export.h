#pragma once

// glTF 2.0 output of the shadowed database (docs/scene-format.md, "glTF export"): the
// faces split into the regions lit by the same set of lights (as obj_export.h splits them),
// or one sun path's sun-hours regions by band of hours (as sun_hours_export.h groups them),
// one material per light set or band, so that any glTF viewer (three.js, Cesium, Blender)
// shows the shadows. Made from the shadowed database alone; written by tinygltf.
//
//   std::string glb = gltf_export(shadowed, GltfForm::kBinary);
//   std::string map = sun_hours_gltf_export(shadowed, path, hour_bands(path), GltfForm::kText);
//
// Layout: one buffer of two views, every mesh's positions, then every mesh's indices; one
// unnamed mesh per material that has triangles, of one primitive
// (TRIANGLES, uint32 indices, float32 POSITION; no NORMAL, so that viewers take each
// triangle's flat normal from its winding, as glTF asks); one node per such mesh, named
// as its material, all children of one root node whose translation is the centre of the
// scene's bounding box. The root is the scene's only node.
//
// Axes: the scene's +z up is glTF's +y up, a point (x, y, z) of the scene is (x, z, −y)
// in glTF (a rotation, so the front side stays the counter-clockwise one; the scene
// reader's glTF import maps (x, y, z) back by (x, −z, y)). Positions are float32 relative
// to the root's translation, which is a double: rounded to nearest, each coordinate is off
// by at most 2^-24 of the scene's half-extent (30 µm for a district 1 km across) however
// far the scene lies from the origin, and a region's area by at most about its perimeter
// times that; at projected coordinates of 4.5e5 float32's own spacing is 0.03.
//
// Pieces: each region is written once, triangulated in its part's plane chart by ear
// clipping (clipper/triangulate.h) on its own vertices (hsr/chart_triangles.h), as the OBJ
// export triangulates it (a polygon of more than 256 vertices in tiles, obj_export.h),
// triangles without area left out; a vertex is shared by the
// triangles of one face in one mesh. Materials are two-sided (doubleSided) and unlit
// (KHR_materials_unlit, in extensionsUsed only: a viewer without it shades the same base colour),
// their baseColorFactor the light set's colour (light_set_colour, obj_export.h) or the band's
// (hour_bands.h), both sRGB, taken to glTF's linear values by the sRGB transfer function;
// names as the MTL's but not escaped: light_set_name() ("sun+lamp", "shadow", with "~2",
// ... where two sets' names are equal), the band's name ("2-4h"). Light sets are those
// some region has, in LightSetLess order; every band is a material, even one without
// regions (which has no mesh), so the materials are the legend.
//
// Extras (JSON, arrays by column so that a district of 36,000 faces costs a few numbers
// per face):
//   scene.extras:   "shadowgen": "light sets" or "sun hours"
//                   "origin": [x, y, z], the root's translation in scene coordinates
//                   "site": {"latitude_deg", "longitude_deg", "elevation_m",
//                            "utc_offset_h", "north_axis_deg"}, where the scene has one
//                   "faces": {"id": [...], "area": [...], "lit_area": [...]}, every face
//                            in scene order, faces without area included; lit_area (area
//                            reached by some light: its regions of non-empty sets) for
//                            light sets only
//                   "lights": [ids] (light sets), or "sun_path": {"id", "step_min",
//                            "instants", "most_hours", "caption": [lines]} (sun hours)
//   material.extras: "lights": [ids] of the set, or "label" ("2–4 h"), "from", "to" (hours)
//                    of the band
//   mesh.extras:    "pieces": {"face": [...], "first_triangle": [...], "area": [...]} and,
//                   for sun hours, "hours": [...]: piece k is face face[k]'s region (light
//                   set) or regions of one number of hours (band) in this mesh, an index
//                   into scene.extras.faces; its triangles run from first_triangle[k] up
//                   to first_triangle[k + 1] (the last piece's to the primitive's end);
//                   area is its area in the database (double), hours its sun hours.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/hour_bands.h"

namespace shadowgen {

enum class GltfForm {
  kBinary,  // .glb: the JSON chunk, then the buffer as the binary chunk
  kText,    // .gltf: JSON, the buffer embedded as a base64 data URI
};

// What a file may hold beyond the layout above, for a reader that shows it (the viewer
// page, shadowgen/viewer/viewer_model.h); `export` writes neither.
struct GltfOptions {
  // Every triangle mesh's vertices carry a float32 attribute _FACE, the index in the scene
  // of the face they lie on (exact below 2^24 faces), so that a reader names the face
  // under a point without the pieces' extras. In a view of its own after the indices'.
  bool face_attribute = false;
  // One more mesh after the materials' (mode LINES, no material, not indexed; its node,
  // "outlines", a child of the root): every face part's outer loop and holes, each edge a
  // pair of vertices, in the same axes and relative to the same root as the triangles.
  bool outlines = false;
};

// A light-set export's bytes, and its materials' light sets (the indices of their lights
// in the scene, ascending) and names, in the materials' order: what a legend lists.
struct LightSetGltf {
  struct Material {
    std::vector<std::size_t> lights;
    std::string name;
  };
  std::string bytes;
  std::vector<Material> materials;
};

// The form a file name asks for by its extension, ".glb" or ".gltf" (in any case);
// nullopt for any other name.
std::optional<GltfForm> gltf_form_of(std::string_view file_name);

// The file's bytes. Throws GenerationError naming the face should a region fail to
// triangulate (valid regions do not), and std::length_error for a model of more than 2^32 − 1
// vertices or 4 GiB.
std::string gltf_export(const ShadowedScene& shadowed, GltfForm form,
                        const GltfOptions& options = {});
LightSetGltf light_set_gltf(const ShadowedScene& shadowed, GltfForm form,
                            const GltfOptions& options = {});

// The bytes of `path`'s sun-hours regions by band (`bands`, its hour bands). `path` is one
// of shadowed.sun_paths, its regions shaped [face] (std::invalid_argument otherwise); throws
// InputError where the path kept no regions (generate --areas-only), and otherwise as
// gltf_export.
std::string sun_hours_gltf_export(const ShadowedScene& shadowed, const SunPathHours& path,
                                  const HourBands& bands, GltfForm form,
                                  const GltfOptions& options = {});

}  // namespace shadowgen
