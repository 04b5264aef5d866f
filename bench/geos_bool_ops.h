#pragma once

// GEOS 3.11 (C API, reentrant) as a competitor: subject ∩ clip and subject − clip.
//
// The constructor builds both GEOS polygons (untimed, as a GEOS user keeps geometries
// in GEOS form); run(), the timed part, is GEOSIntersection_r plus GEOSDifference_r on
// them (the OverlayNG engine, floating precision, with its snapping fallback) and the
// freeing of the previous run's results. result() converts the last results back,
// untimed.

#include <memory>

#include "clipper/clip.h"

namespace shadowgen::bench {

class GeosBoolOps {
 public:
  GeosBoolOps(const clipper::PolygonWithHoles2& subject,
              const clipper::PolygonWithHoles2& clip_region);
  ~GeosBoolOps();
  GeosBoolOps(const GeosBoolOps&) = delete;
  GeosBoolOps& operator=(const GeosBoolOps&) = delete;

  // GEOSisValid_r on both inputs: the workload's own sanity check.
  bool inputs_valid() const;
  void run();
  clipper::ClipResult result() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowgen::bench
