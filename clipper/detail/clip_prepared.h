#pragma once

// clip() for a subject its caller has already prepared, for the clipper's own callers
// that need its vertices kept (tiles.h).

#include "clipper/clip.h"
#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

// clip(subject, clip_region) for a subject taken as it is given, without clip()'s first
// cleaning: outer loops counter-clockwise, holes clockwise, no repeated vertices and no
// spikes (remove_spikes, normalize.h), but vertices where a loop runs straight on left
// in, so that they stay vertices of the pieces. The clip region is normalized as clip()
// normalizes it.
ClipResult clip_prepared(PolygonSet2 subject, const PolygonSet2& clip_region);

}  // namespace shadowgen::clipper::detail
