#include "shadowgen/sampled/ray_caster.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <string>

namespace shadowgen::sampled {
namespace {

void check(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(error)) + ")");
  }
}

}  // namespace

RayCaster::RayCaster(RTCDevice device, std::span<const Triangle3> occluders)
    : scene_(rtcNewScene(device)) {
  if (scene_ == nullptr) check(device, "making a scene");
  // Robust: watertight edges, at a small cost in speed.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  double magnitude = 0.0;
  if (!occluders.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* xyz = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                            RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                            3 * occluders.size()));
    auto* index = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), occluders.size()));
    if (xyz == nullptr || index == nullptr) {
      rtcReleaseGeometry(geometry);
      rtcReleaseScene(scene_);
      check(device, "geometry buffers");
      throw std::runtime_error("embree: geometry buffers failed");
    }
    unsigned next = 0;
    for (const Triangle3& t : occluders) {
      for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
        magnitude = std::max({magnitude, std::fabs(v->x), std::fabs(v->y), std::fabs(v->z)});
        *xyz++ = static_cast<float>(v->x);
        *xyz++ = static_cast<float>(v->y);
        *xyz++ = static_cast<float>(v->z);
        *index++ = next++;
      }
    }
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
  offset_ = kOffsetUlps * 0x1.0p-23 * magnitude;
}

RayCaster::~RayCaster() { rtcReleaseScene(scene_); }

double RayCaster::lit(const Light& light, const glm::dvec3& point, const glm::dvec3& normal) const {
  const glm::dvec3 origin = point + offset_ * normal;
  glm::dvec3 direction;
  float tfar = std::numeric_limits<float>::infinity();
  if (light.type == LightType::kDirectional) {
    direction = -light.direction;
  } else {
    // The light at t = 1 along the unnormalised direction; stop the offset short of it.
    direction = light.position - origin;
    const double length = glm::length(direction);
    if (!(length > 2.0 * offset_)) return 1.0;  // the light on the part: nothing between
    tfar = std::min(static_cast<float>(1.0 - offset_ / length), std::nextafter(1.0f, 0.0f));
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  ray.org_x = static_cast<float>(origin.x);
  ray.org_y = static_cast<float>(origin.y);
  ray.org_z = static_cast<float>(origin.z);
  ray.dir_x = static_cast<float>(direction.x);
  ray.dir_y = static_cast<float>(direction.y);
  ray.dir_z = static_cast<float>(direction.z);
  ray.tnear = 0.0f;
  ray.tfar = tfar;
  ray.time = 0.0f;
  ray.mask = std::numeric_limits<unsigned>::max();
  ray.id = 0;
  ray.flags = 0;
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar >= 0.0f ? 1.0 : 0.0;  // Embree sets tfar to -inf on a hit
}

}  // namespace shadowgen::sampled
