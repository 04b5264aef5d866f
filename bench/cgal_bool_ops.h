#pragma once

// CGAL 5.5 exact Boolean operations (Epeck kernel, Boolean_set_operations_2) as a
// competitor and as the exact reference of the accuracy counters. CGAL is compiled in
// cgal_bool_ops.cpp only; this header shows no CGAL type.
//
// The constructor converts both polygons to CGAL (untimed: every double is exactly
// representable, so the conversion decides nothing); run(), the timed part, is
// CGAL::intersection plus CGAL::difference on them and the freeing of the previous
// results.

#include <memory>

#include "clipper/clip.h"

namespace shadowgen::bench {

class CgalBoolOps {
 public:
  CgalBoolOps(const clipper::PolygonWithHoles2& subject,
              const clipper::PolygonWithHoles2& clip_region);
  ~CgalBoolOps();
  CgalBoolOps(const CgalBoolOps&) = delete;
  CgalBoolOps& operator=(const CgalBoolOps&) = delete;

  void run();
  // The last run's pieces with every coordinate rounded to the nearest double.
  clipper::ClipResult result() const;

 private:
  friend class ExactAreaReference;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The exact areas of subject ∩ clip and subject − clip (CGAL's exact result), against
// which any clipper's output is measured.
class ExactAreaReference {
 public:
  // Runs CGAL once; slow for large inputs.
  ExactAreaReference(const clipper::PolygonWithHoles2& subject,
                     const clipper::PolygonWithHoles2& clip_region);
  ~ExactAreaReference();
  ExactAreaReference(ExactAreaReference&&) noexcept;
  ExactAreaReference& operator=(ExactAreaReference&&) noexcept;

  // (|A_in − A*_in| + |A_out − A*_out|) / (A*_in + A*_out), A* the exact areas and A
  // those of `result` taken exactly over its double coordinates (|outer| minus |holes|,
  // orientation ignored); all in rational arithmetic, rounded once at the end. So it
  // measures the output polygons, not the rounding of a floating-point area sum, and it
  // is 0 only for a result of exactly the right area.
  double relative_area_error(const clipper::ClipResult& result) const;

 private:
  struct Areas;
  std::unique_ptr<Areas> areas_;
};

}  // namespace shadowgen::bench
