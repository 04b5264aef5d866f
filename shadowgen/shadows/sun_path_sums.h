#pragma once

// A run's sun paths summed as their instants come (docs/scene-format.md, "Sun hours"), face
// by face: each block of instants (sun_hours_tree.h) added instant by instant, the blocks
// joined in the path's tree. With a shard, only its own instants are summed, and its nodes
// are what it keeps. The generators (generate.h, estimate_shadows.h) add each batch of
// lights they work out, in light order, so that the sums are made in one order whatever
// the thread count.

#include <cstddef>
#include <optional>
#include <set>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/shadows/sun_hours.h"
#include "shadowgen/shadows/sun_hours_tree.h"

namespace shadowgen {

class SunPathSums {
 public:
  // Sets up `paths` (sun_paths_of(scene)) to be summed: lit areas always; sun-hours regions
  // (or, in a shard, the tree's nodes) where `regions`. `scene` and `paths` must outlive it.
  SunPathSums(const Scene& scene, std::vector<SunPathHours>& paths, bool keep_polygons,
              bool regions, const std::optional<ShardPlace>& shard);

  // Whether light `light` is an instant of some path (this shard's or not).
  bool in_path(std::size_t light) const { return in_any_path_.count(light) > 0; }
  // The lights this run works out, in order: in a shard, its own instants, and the lights
  // that are no instant in shard 0 alone; otherwise every light.
  std::vector<std::size_t> lights_of_run() const;

  // Adds the lit polygons of lights `batch`, lit[i][face] for light batch[i], to their
  // paths, in light order, each face on its own. Throws GenerationError (naming the face
  // and the path) where a sum cannot be computed.
  void add_lit(const std::vector<std::size_t>& batch,
               const std::vector<std::vector<std::vector<LitPolygon>>>& lit);
  // Adds a sampled method's lit areas of lights `batch`, estimated[i][face][part].
  void add_estimated(const std::vector<std::size_t>& batch,
                     const std::vector<std::vector<std::vector<double>>>& estimated);

  // Every path's regions (or, in a shard, its nodes), once all its instants are added.
  void finish();

 private:
  // Where each light stands in the paths: (path, k) for instant k of a path.
  struct PathPlace {
    std::size_t path = 0, instant = 0;
  };
  struct PathState {
    std::size_t first = 0, last = 0;                 // the instants summed here
    std::vector<std::optional<FaceSunHours>> block;  // [face]: the block being summed
    std::vector<SunHoursNodes> nodes;                // [face]
  };

  // Calls work(i, face, path, instant) for each light batch[i] this run sums, each face on
  // a thread of its own, in light order within the face.
  template <class Work>
  void each_summed(const std::vector<std::size_t>& batch, Work&& work);
  // Work on face f's sums of path p, a failure named by the face and the path.
  template <class Work>
  void named(std::size_t f, std::size_t p, Work&& work) const;

  const Scene& scene_;
  std::vector<SunPathHours>& paths_;
  bool regions_ = true;
  std::optional<ShardPlace> shard_;
  std::vector<std::optional<PathPlace>> place_;
  std::set<std::size_t> in_any_path_;
  std::vector<PathState> state_;  // [path]
};

}  // namespace shadowgen
