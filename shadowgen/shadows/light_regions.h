#pragma once

// The partition of a face by the set of lights that reach it: where several lights shine,
// the paper's lit details of each light overlap, and a renderer or an OBJ file wants the
// pieces lit by exactly one combination. Computed from the shadowed database alone.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

// One region of a face lit by exactly the lights in `lights` (indices into scene.lights,
// ascending; empty: in shadow from every light). Polygons in the face's plane(s), scene
// coordinates, like the lit detail polygons: outer loops counter-clockwise seen from the
// face's front side, holes the other way; each on the part of the face it names.
struct LightRegion {
  std::vector<std::size_t> lights;
  std::vector<LitPolygon> polygons;
};

// The order of light sets used everywhere they are listed (regions, OBJ materials): the
// empty set first, then by size, then lexicographically.
struct LightSetLess {
  bool operator()(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) const {
    if (a.size() != b.size()) return a.size() < b.size();
    return a < b;
  }
};

// Partition of face `face` of `shadowed` into regions by the set of lights reaching them:
// disjoint, covering the face exactly, no region with an empty polygon list, sets in a
// deterministic order (empty set first, then by size, then lexicographically).
//
// Method: each part of the face (one, or the triangles of a non-planar polygon) is taken
// to its exact plane chart (hsr/plane_chart.h); the part's pieces are split
// by each light's lit polygons in turn, every piece going to "inside" (the light joins
// its set) or "outside". Only pieces that the light's shadow edges pass through are
// clipped, with the Weiler–Atherton clipper, against the lit polygons near them; the
// others are sorted by their boxes or, exactly, by where they lie (detail/chart_region.h).
// Each lit polygon splits the part it carries
// (LitPolygon::part). Chart points that are
// vertices of the part are lifted back to those exact 3D points; every other point (lit polygons'
// vertices, which generation leaves within rounding of the plane, and new crossings)
// gets the part's plane's coordinate along the dropped axis. So the regions' areas
// sum to the face's area, and the regions containing a light to its lit area, up to the
// clipper's rounding of crossing points (clipper/clip.h). Faces or parts without area
// give no regions. Throws GenerationError naming the face where a clip's snap rounding
// does not settle (clipper/clip.h), and std::invalid_argument when `face` is out of range.
std::vector<LightRegion> light_regions(const ShadowedScene& shadowed, std::size_t face);

// "sun+lamp" style name of a light set from the lights' ids, in the set's order; "shadow"
// for the empty set. Ids are used as they are (an id holding '+' makes names ambiguous).
std::string light_set_name(const Scene& scene, std::span<const std::size_t> lights);

}  // namespace shadowgen
