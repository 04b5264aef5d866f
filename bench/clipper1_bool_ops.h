#pragma once

// Clipper 1 (Angus Johnson's ClipperLib 6.4, integer coordinates) as a competitor:
// subject ∩ clip and subject − clip from one pair of double-precision polygons.
//
// What run() does, all of it timed: round both polygons to Clipper's 64-bit integer
// grid, add them to one Clipper, then execute an intersection and a difference
// (even-odd fill on both). The grid scale is 1e9 / (largest |coordinate| of the pair),
// so every integer is at most 1e9 in magnitude, below Clipper's loRange (2^30 − 1),
// and Clipper stays on its fast 64-bit products rather than its 128-bit ones. The
// rounding moves every input vertex by up to half a grid step, which is what the
// accuracy counter of the benchmark sees.
//
// Output::kPolyTree returns the outer/hole nesting (the equivalent of shadowgen's
// ClipResult); Output::kPaths returns flat rings, Clipper's cheapest form. result()
// converts back to doubles, untimed, and needs kPolyTree.

#include <memory>

#include "clipper/clip.h"

namespace shadowgen::bench {

class Clipper1BoolOps {
 public:
  enum class Output { kPolyTree, kPaths };

  Clipper1BoolOps(const clipper::PolygonWithHoles2& subject,
                  const clipper::PolygonWithHoles2& clip_region, Output output);
  ~Clipper1BoolOps();
  Clipper1BoolOps(const Clipper1BoolOps&) = delete;
  Clipper1BoolOps& operator=(const Clipper1BoolOps&) = delete;

  void run();
  clipper::ClipResult result() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowgen::bench
