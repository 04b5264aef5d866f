#pragma once

// Shadows per pixel by Thakur, Cheng and Miura's discretised shadow volumes in angular
// coordinates ("Shadow generation using discretized shadow volume in angular coordinates",
// and Thakur and Cheng's long version on ridge-edge loops):
//
//   1. Per light, the parts it takes into account (light_scope.h: kLeftOut parts neither
//      receive nor occlude) are joined into objects through shared edges; each part is
//      visible (front facing the light) or hidden; ridge edges (one adjacent face visible,
//      one hidden) are followed into RE loops (detail/ridge_edge_loops.h).
//   2. Angular coordinates (detail/angular_frame.h): from a point light, θ = atan(Y/W),
//      φ = atan(X/W), r the distance, in a frame at the light whose −Z axis (W) aims at the
//      centre of the parts' bounding box; the two hemispheres W >= 0 and W < 0 each get a
//      table (the papers' "light source in the scene", without their variable-resolution
//      rows). From a directional light, the light's orthographic frame: θ and φ the two
//      coordinates across its direction, r the distance along it.
//   3. The angular span table (detail/angular_span_table.h): θ cut into `resolution` rows;
//      per row, the pairs (φa, ra)–(φb, rb) between crossings of ridge and hidden edges
//      with the row's plane, each on one hidden face (pair correctness), carrying the depth
//      of the object's far side (the papers' depth information).
//   4. Per pixel, the point's row, a binary search for the pairs holding its φ, and the
//      depth test: in shadow where an occluder's depth there is less than the point's.
//      An object does not shadow its own visible faces (its hidden faces lie beyond them),
//      but a concave one shadows itself where one part's hidden face stands before another
//      part's visible face.
//
// Not implemented: the run-length computation and maximum run length of section 6 (they
// speed up a scan-line rasteriser; here each pixel is looked up on its own), and the VREPIP
// decomposition of the long version's section 2.2 (the papers' table makes it unneeded).
// The variable-resolution table of section 11.2 was tried and left out: rows equal in
// tan θ (equation 4) up to where they are 1/16 as wide as at θ = 0, then equal in θ,
// against equal rows, on a lamp inside a grid of cubes (AngularShadows.
// PointLightInsideTheGridUsesBothHemispheres' scene), pixels off boundaries disagreeing
// with volumes: 5.5 % against 0.57 % at 32 rows, 1.3 % against 0.044 % at 128, 0.073 %
// against 0 at 512. Narrowing the rows towards θ = ±π/2 takes them from the middle of the
// hemisphere, where a scene around a light stands in front of it; equal rows keep it.
//
// Limitations, as the papers state them: objects are closed 3-manifolds (every edge shared
// by exactly two faces, no dangling faces). Here, for other models: an open edge never is a
// ridge edge, a hidden face still enters the table with its open edges ending its spans, so
// a dangling face turned away from the light shadows what lies behind it; but a visible face
// enters no table (only hidden faces carry depth), so a dangling face that faces the light
// — an open model seen from its outside, a lone quad, a box without its bottom lit from
// below — casts no shadow. Shadows are exact up to the discretisation of θ: a point is
// looked up in the row of its θ, sliced at the row's centre, so boundaries running across
// the rows shift by up to half a row.

#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/view/pixel_surfaces.h"

namespace shadowgen {

// Per pixel of `surfaces` (shadowgen/view/pixel_surfaces.h: the surface seen through each
// pixel centre, its 3D point, part, normal, front side), whether `light` reaches it, by
// Thakur, Cheng and Miura's discretised shadow volumes in angular coordinates: 1 lit, 0 in
// shadow; 0 also for no surface, a back side, or a part not facing the light (light_scope.h:
// kFacing only). `resolution`: rows of the angular span table (the discretisation of the
// vertical angle θ), at least 1. `surfaces` must have been seen in `scene`. Throws
// std::invalid_argument for a resolution below 1.
std::vector<double> angular_lit_weights(const Scene& scene, const Light& light,
                                        const PixelSurfaces& surfaces, int resolution);

}  // namespace shadowgen
