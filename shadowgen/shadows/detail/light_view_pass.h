#pragma once

// What one light view lights, in three stages:
//   1. hidden-surface removal from the light: what of each receiver the view sees;
//   2. coplanar receivers (coplanar_receivers.h): what it sees of a receiver's plane
//      within the receiver's image, also where a coplanar neighbour got the fragment;
//   3. back-projection: each lit receiver's pieces merged and cast back onto its plane,
//      as this view's lit polygons of that part.

#include <vector>

#include "hsr/hidden_surface.h"
#include "hsr/view.h"
#include "lit_parts.h"
#include "receivers.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::shadows::detail {

// Appends this view's lit polygons to `lit` (indexed like the FaceParts) for every
// receiver the view lights; counts the fragments in stats.fragments. `hsr`: how the
// view's hidden surfaces are removed (its image regions).
void light_through_view(const Receivers& receivers, const hsr::View& view,
                        const hsr::HsrOptions& hsr, std::vector<LitPart>& lit, LightStats& stats);

}  // namespace shadowgen::shadows::detail
