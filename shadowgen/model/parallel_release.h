#pragma once

// A shadowed scene's storage freed face by face on the calling task arena's threads: a
// city's faces, parts and lit polygons are hundreds of thousands of blocks, which one
// thread freeing at the end of a command took about 0.3 % of its instructions, serial.

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

// Frees each face of `shadowed` (its id, parts and origin) and its lit polygons under
// every light the table keeps, in parallel; leaves as many faces, each empty, and every
// kept list empty, for the destructor to pass over. Whatever else `shadowed` holds (sun
// paths, estimates) is left to it. Calls may not share `shadowed`.
void release_faces_in_parallel(ShadowedScene& shadowed);

}  // namespace shadowgen
