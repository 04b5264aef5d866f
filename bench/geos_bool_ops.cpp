#include "bench/geos_bool_ops.h"

#include <geos_c.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace shadowgen::bench {
namespace {

using clipper::Loop2;
using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

void record_error(const char* message, void* user_data) {
  *static_cast<std::string*>(user_data) = message;
}

}  // namespace

struct GeosBoolOps::Impl {
  GEOSContextHandle_t context = nullptr;
  std::string last_error;
  GEOSGeometry* subject = nullptr;
  GEOSGeometry* clip_region = nullptr;
  GEOSGeometry* inside = nullptr;
  GEOSGeometry* outside = nullptr;

  [[noreturn]] void fail(const char* what) const {
    throw std::runtime_error(std::string("GEOS: ") + what + ": " + last_error);
  }

  // A closed GEOS ring: the first vertex repeated at the end.
  GEOSGeometry* ring(const Loop2& loop) {
    std::vector<double> xy;
    xy.reserve(2 * loop.size() + 2);
    for (const auto& p : loop) xy.insert(xy.end(), {p.x, p.y});
    xy.insert(xy.end(), {loop.front().x, loop.front().y});
    GEOSCoordSequence* sequence = GEOSCoordSeq_copyFromBuffer_r(
        context, xy.data(), static_cast<unsigned>(loop.size() + 1), 0, 0);
    if (sequence == nullptr) fail("GEOSCoordSeq_copyFromBuffer_r");
    GEOSGeometry* r = GEOSGeom_createLinearRing_r(context, sequence);
    if (r == nullptr) fail("GEOSGeom_createLinearRing_r");
    return r;
  }

  GEOSGeometry* polygon(const PolygonWithHoles2& p) {
    GEOSGeometry* shell = ring(p.outer);
    std::vector<GEOSGeometry*> holes;
    for (const auto& hole : p.holes) holes.push_back(ring(hole));
    GEOSGeometry* g =
        GEOSGeom_createPolygon_r(context, shell, holes.data(), static_cast<unsigned>(holes.size()));
    if (g == nullptr) fail("GEOSGeom_createPolygon_r");
    return g;
  }

  Loop2 loop_of(const GEOSGeometry* geos_ring) const {
    const GEOSCoordSequence* sequence = GEOSGeom_getCoordSeq_r(context, geos_ring);
    unsigned size = 0;
    if (sequence == nullptr || GEOSCoordSeq_getSize_r(context, sequence, &size) == 0) {
      fail("GEOSGeom_getCoordSeq_r");
    }
    std::vector<double> xy(2 * size);
    if (size > 0 && GEOSCoordSeq_copyToBuffer_r(context, sequence, xy.data(), 0, 0) == 0) {
      fail("GEOSCoordSeq_copyToBuffer_r");
    }
    Loop2 loop;
    for (unsigned i = 0; i + 1 < size; ++i) loop.push_back({xy[2 * i], xy[2 * i + 1]});
    return loop;  // the closing repeat of the first vertex dropped
  }

  // Polygons of a Polygon, MultiPolygon or (empty) GeometryCollection result.
  void collect(const GEOSGeometry* g, PolygonSet2& out) const {
    if (GEOSisEmpty_r(context, g) == 1) return;
    if (GEOSGeomTypeId_r(context, g) == GEOS_POLYGON) {
      PolygonWithHoles2 p;
      p.outer = loop_of(GEOSGetExteriorRing_r(context, g));
      const int holes = GEOSGetNumInteriorRings_r(context, g);
      for (int i = 0; i < holes; ++i)
        p.holes.push_back(loop_of(GEOSGetInteriorRingN_r(context, g, i)));
      out.push_back(std::move(p));
      return;
    }
    const int parts = GEOSGetNumGeometries_r(context, g);
    for (int i = 0; i < parts; ++i) collect(GEOSGetGeometryN_r(context, g, i), out);
  }

  void destroy(GEOSGeometry*& g) {
    if (g != nullptr) GEOSGeom_destroy_r(context, g);
    g = nullptr;
  }
};

GeosBoolOps::GeosBoolOps(const PolygonWithHoles2& subject, const PolygonWithHoles2& clip_region)
    : impl_(std::make_unique<Impl>()) {
  impl_->context = GEOS_init_r();
  GEOSContext_setErrorMessageHandler_r(impl_->context, record_error, &impl_->last_error);
  impl_->subject = impl_->polygon(subject);
  impl_->clip_region = impl_->polygon(clip_region);
}

GeosBoolOps::~GeosBoolOps() {
  impl_->destroy(impl_->inside);
  impl_->destroy(impl_->outside);
  impl_->destroy(impl_->subject);
  impl_->destroy(impl_->clip_region);
  GEOS_finish_r(impl_->context);
}

bool GeosBoolOps::inputs_valid() const {
  return GEOSisValid_r(impl_->context, impl_->subject) == 1 &&
         GEOSisValid_r(impl_->context, impl_->clip_region) == 1;
}

void GeosBoolOps::run() {
  Impl& s = *impl_;
  s.destroy(s.inside);
  s.destroy(s.outside);
  s.inside = GEOSIntersection_r(s.context, s.subject, s.clip_region);
  if (s.inside == nullptr) s.fail("GEOSIntersection_r");
  s.outside = GEOSDifference_r(s.context, s.subject, s.clip_region);
  if (s.outside == nullptr) s.fail("GEOSDifference_r");
}

clipper::ClipResult GeosBoolOps::result() const {
  clipper::ClipResult r;
  if (impl_->inside != nullptr) impl_->collect(impl_->inside, r.inside);
  if (impl_->outside != nullptr) impl_->collect(impl_->outside, r.outside);
  return r;
}

}  // namespace shadowgen::bench
