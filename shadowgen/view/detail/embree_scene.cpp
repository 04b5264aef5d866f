#include "detail/embree_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace shadowgen::detail {
namespace {

void check(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(error)) + ")");
  }
}

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
    : scene_(rtcNewScene(device)), centre_(centre) {
  if (scene_ == nullptr) check(device, "making a scene");
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  if (!triangles.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* xyz = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                            RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                            3 * triangles.size()));
    auto* index = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), triangles.size()));
    if (xyz == nullptr || index == nullptr) {
      rtcReleaseGeometry(geometry);
      rtcReleaseScene(scene_);
      check(device, "geometry buffers");
      throw std::runtime_error("embree: geometry buffers failed");
    }
    unsigned next = 0;
    for (const sampled::Triangle3& t : triangles) {
      for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
        const glm::dvec3 p = *v - centre_;
        magnitude_ = std::max({magnitude_, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
        *xyz++ = static_cast<float>(p.x);
        *xyz++ = static_cast<float>(p.y);
        *xyz++ = static_cast<float>(p.z);
        *index++ = next++;
      }
    }
    rtcSetGeometryIntersectFilterFunction(geometry, record_and_reject);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene_);
  try {
    check(device, "building the hierarchy");
  } catch (...) {
    rtcReleaseScene(scene_);
    throw;
  }
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

}  // namespace shadowgen::detail
