#pragma once

// Wavefront OBJ + MTL output of the shadowed database: every face split into the regions
// lit by the same set of lights (shadowgen/shadows/light_regions.h), one material per set, so any
// OBJ viewer shows the shadows. Made from the shadowed database alone.
//
// OBJ layout, faces in scene order (polygons, then mesh faces):
//
//   # shadowgen OBJ export: faces split by the set of lights reaching them
//   mtllib scene.mtl
//   g <face id>                  one group per face, also for faces without area (empty)
//   v x y z                      the face's vertices, scene coordinates
//   vn x y z                     unit normal of each of the face's planes, front side
//   usemtl <light set name>      each region of the face, sets in light_regions' order
//   f a//n b//n c//n             its triangles, counter-clockwise seen from the front
//
// Numbers are the shortest decimal form that reads back to the same double, so the
// vertices are the regions' vertices bit for bit. Regions are triangulated in their
// part's plane chart by ear clipping (clipper/triangulate.h) on their own
// vertices: no point is added, and the triangles of a region cover exactly its polygons
// (triangles whose corners are exactly collinear, which add no area, are left out). A
// polygon of more than 256 vertices (a ground's lit region with a hole per building) is
// first cut into tiles along lines parallel to its chart's axes (hsr/chart_triangles.h,
// tiled_chart_triangles), so that its triangulation costs time near linear in its
// vertices: its own vertices are kept, the cut lines' crossings are added on the part's
// plane, and its triangles cover it up to the clipper's rounding of those crossings. Vertex
// and normal numbers are global and 1-based, as OBJ counts them; a face's vertices and
// normals come right after its `g` line and are not shared with other faces.
//
// Names: group and material names are obj_name() of the face id and of light_set_name()
// ("sun+lamp", "shadow"). Should two light sets' names come out equal after that, the
// later set's gets "~2", "~3", ... appended, so every material name stands for one set;
// each material's lights are also listed in a comment line above it in the MTL.
//
// Colour rule (MTL Kd, and Ka the same), per channel c, for a set S of lights with
// intensities I:
//     Kd_c = kAmbientGrey + (1 − kAmbientGrey) · Σ_{l∈S} max(I_l,c, 0) / Σ_{all l} max(I_l,c, 0)
// clamped to [0, 1]; a channel whose total is 0 gets kAmbientGrey. So the shadow (S
// empty) is grey 0.2, the region every light reaches is white, and a region reached by
// some light of positive intensity is lighter than the shadow. Fall-off with distance is
// not modelled (a material is one colour). Ks is 0 0 0, d is 1, illum is 1.

// By light (obj_export_by_light): what each light reaches, one layer per light over the
// face in shadow, in time and size linear in the lights. (The light-set regions above are
// the arrangement of every light's shadow edges, which grows faster: 100 suns sweeping a
// face split it into thousands of sets.) Per face, in scene order:
//
//   g <face id>                  the face whole, in shadow (faces without area: empty)
//   v x y z, vn x y z            as above, shared by all the face's groups
//   usemtl shadow
//   f ...                        the face's parts
//   g <face id>@<light id>       one group per light with lit polygons on the face, lights
//   usemtl <light id>            in scene order: the light's lit polygons, triangulated
//   f ...                        as regions are above
//
// The layers lie on their face and on one another: a viewer shows the groups it is asked
// to, or a light's layer and the shadow beneath it. Materials: "shadow", then one per light
// reaching some face, in scene order, named obj_name(light id) (~2, ~3, ... where a name
// is taken) and coloured by the colour rule for the set of that light alone. In these
// group names the face id has '@' escaped too (%40), so it is what comes before the first
// '@' and the light id what follows it.

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <string_view>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

inline constexpr double kAmbientGrey = 0.2;

// A name as OBJ and MTL statements can hold it (one word, no comment), escaped so that
// distinct names stay distinct and the original can be read back: each byte that is
// whitespace, a control character, '#' (a comment), '%' (the escape) or outside
// printable ASCII becomes %XX, its value in upper-case hex ("a b" is "a%20b", "a_b" stays
// "a_b", "café" is "caf%C3%A9"). The empty name, which no id is, becomes "%".
std::string obj_name(std::string_view name);

// The MTL Kd of a light set (the colour rule above); `lights` as in LightRegion.
glm::dvec3 light_set_colour(const Scene& scene, std::span<const std::size_t> lights);

struct ObjFiles {
  std::string obj;
  std::string mtl;
};

// Both texts; `mtl_file_name` is what the OBJ's `mtllib` line names (the MTL's file name,
// next to the OBJ). Throws GenerationError naming the face should a region fail to
// triangulate (valid regions do not).
ObjFiles obj_export(const ShadowedScene& shadowed, std::string_view mtl_file_name);

// The layers by light (above); throws as obj_export does, naming the face and the light
// whose lit polygons fail to triangulate.
ObjFiles obj_export_by_light(const ShadowedScene& shadowed, std::string_view mtl_file_name);

}  // namespace shadowgen
