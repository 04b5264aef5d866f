#pragma once

// What one light lights of each face part, gathered view by view, and the last two stages
// of its shadows: the parts it grazes worked out again in their own planes, and each
// part's views joined into the lit polygons of its face.

#include <vector>

#include "face_parts.h"
#include "hsr/polygon3.h"
#include "receivers.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::shadows::detail {

// The lit polygons of one face part, one list per light view that saw some of it (a
// point light may see a part through several frusta).
struct LitPart {
  std::vector<std::vector<hsr::Polygon3>> by_view;
  // Some view's rounding, cast back, may carry lit points beyond the part's reach
  // (BackProjector::cast_reach): the join cuts them to the part.
  bool may_stray = false;
  // How far the views' rounding, cast back, can move a lit point within the part's plane:
  // the largest BackProjector::reach_of the views' lit image points (0 where the lit region
  // was worked out in the part's own plane).
  double lit_reach = 0.0;
};

// Receivers the light grazes: cast back from its image, their lit region would carry the
// image's rounding divided by a tiny sine; it is worked out in their plane instead
// (grazing_light.h) and replaces what the views gave. Receivers with the light in their
// plane by that measure (Incidence::kInPlane) get nothing. `lit` is indexed like the FaceParts.
// Counts the grazed in stats.faces_grazed.
void relight_grazed_parts(const Receivers& receivers, std::vector<LitPart>& lit, LightStats& stats);

// The lit polygons of every face (parts.face_count lists), each part's views joined into
// one region that stays within the part. A part lit whole, as far as rounding can tell,
// gets the part itself as its one lit polygon, so that its lit area is the part's own area,
// the same number (lit_whole in lit_parts.cpp says when). Counts them in stats.lit_polygons.
std::vector<std::vector<LitPolygon>> join_per_face(const FaceParts& parts, std::vector<LitPart> lit,
                                                   LightStats& stats);

}  // namespace shadowgen::shadows::detail
