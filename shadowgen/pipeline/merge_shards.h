#pragma once

// Joining the shards of a sun-path run (generate --instants K/N) into the shadowed database
// one run of the whole scene makes, byte for byte once written: the lights that are no
// instant come from shard 1, each path's lit areas are the shards' in order, and its sums
// are the shards' tree nodes joined as one run joins them (shadows/sun_hours_tree.h).

#include <string>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

struct ShardFile {
  std::string file;  // names it in messages
  // As the database reader reads it: ShadowedScene::shard set, and nothing beyond the
  // shard's share (the reader refuses lit polygons in any shard but the first, and lit
  // areas or nodes of instants not its own), so the join drops nothing.
  ShadowedScene shadowed;
};

// Throws InputError naming the file (and the face, where one is to blame) where the
// shards are not every shard of one run once: a database that is no shard, shards of
// another count or another scene (faces, lights, views, sun paths), a shard missing or
// given twice, sums that do not fit their face, or a result that fails the checks of
// a database read (shadowgen/scene/database_reader.h). Throws GenerationError (no file) where
// joining a face's sums does not settle, as generate would.
ShadowedScene merge_shards(std::vector<ShardFile> shards);

}  // namespace shadowgen
