#include "detail/embree_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "shadowgen/sampled/embree_triangles.h"

namespace shadowgen::view::detail {
namespace {

// The query's own context: Embree's, then where the hits go.
struct HitContext {
  RTCIntersectContext context;
  std::vector<SegmentHit>* out;
};

// Records the hit and rejects it, so that the traversal goes on.
void record_and_reject(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const HitContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    context->out->push_back(
        {RTCHitN_primID(args->hit, args->N, i), RTCRayN_tfar(args->ray, args->N, i)});
    args->valid[i] = 0;
  }
}

}  // namespace

EmbreeDevice::EmbreeDevice() : device_(rtcNewDevice(nullptr)) {
  if (device_ == nullptr) throw std::runtime_error("embree: no device");
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

TriangleScene::TriangleScene(RTCDevice device, std::span<const sampled::Triangle3> triangles,
                             const glm::dvec3& centre)
    : centre_(centre) {
  const sampled::EmbreeTriangles built =
      sampled::embree_triangles(device, triangles, centre, record_and_reject);
  scene_ = built.scene;
  magnitude_ = built.magnitude;
}

TriangleScene::~TriangleScene() { rtcReleaseScene(scene_); }

void TriangleScene::hits(const glm::dvec3& origin, const glm::dvec3& direction, double tnear,
                         double tfar, std::vector<SegmentHit>& out) const {
  HitContext context;
  rtcInitIntersectContext(&context.context);
  context.out = &out;
  RTCRayHit query;
  const glm::dvec3 o = origin - centre_;
  query.ray.org_x = static_cast<float>(o.x);
  query.ray.org_y = static_cast<float>(o.y);
  query.ray.org_z = static_cast<float>(o.z);
  query.ray.dir_x = static_cast<float>(direction.x);
  query.ray.dir_y = static_cast<float>(direction.y);
  query.ray.dir_z = static_cast<float>(direction.z);
  query.ray.tnear = static_cast<float>(std::max(0.0, tnear));
  query.ray.tfar =
      std::isfinite(tfar) ? static_cast<float>(tfar) : std::numeric_limits<float>::infinity();
  query.ray.time = 0.0f;
  query.ray.mask = std::numeric_limits<unsigned>::max();
  query.ray.id = 0;
  query.ray.flags = 0;
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context.context, &query);
}

}  // namespace shadowgen::view::detail
