#pragma once

// Coplanar faces do not shadow each other (the spec's meaning of "lit"): a receiver that
// faces the light is lit wherever the plane it shares with others is visible within its
// own image. Hidden-surface removal gives an overlap of exactly coplanar faces to one of
// them; here every member of the group counts as a receiver of it, also one that got no
// fragment at all (a rug lying on the ground, whose overlap went to the ground).

#include <vector>

#include "clipper/polygon.h"
#include "hsr/view.h"
#include "receivers.h"

namespace shadowgen::shadows::detail {

// Per receiver: the pieces that `view` saw of the other members of its coplanar group
// (`seen`, per receiver, in image coordinates), within its own image.
std::vector<clipper::PolygonSet2> seen_on_shared_planes(
    const Receivers& receivers, const hsr::View& view,
    const std::vector<clipper::PolygonSet2>& seen);

}  // namespace shadowgen::shadows::detail
