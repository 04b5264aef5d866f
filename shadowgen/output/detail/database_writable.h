#pragma once

// What the database format cannot hold is refused before a byte is written, so that
// every file written reads back (shadowgen/output/database.h).

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::output::detail {

// Throws std::invalid_argument ("shadowed database: <owner>: what") where `shadowed`
// has two faces, lights or views of one id, a coordinate, area or hour that is not
// finite, a loop of fewer than three vertices, a lit polygon on no part of its face, or
// sums of a sun path not shaped per face and instant (in a shard, per instant of its own).
void check_writable(const ShadowedScene& shadowed);

}  // namespace shadowgen::output::detail
