#include "shadowgen/sampled/ray_caster.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "shadowgen/sampled/embree_triangles.h"

namespace shadowgen::sampled {
namespace {

// The widest packet Embree traverses natively on this CPU (1: none).
int native_packet_width(RTCDevice device) {
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) return 16;
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) return 8;
  if (rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) return 4;
  return 1;
}

// The shadow ray of `point` (module comment), or false where the light is on the part:
// lit with nothing between, no ray to cast. Both ways of casting take their rays here.
bool shadow_ray(const Light& light, const glm::dvec3& point, const glm::dvec3& normal,
                double offset, RTCRay& ray) {
  const glm::dvec3 origin = point + offset * normal;
  glm::dvec3 direction;
  float tfar = std::numeric_limits<float>::infinity();
  if (light.type == LightType::kDirectional) {
    direction = -light.direction;
  } else {
    // The light at t = 1 along the unnormalised direction; stop the offset short of it.
    direction = light.position - origin;
    const double length = glm::length(direction);
    if (!(length > 2.0 * offset)) return false;
    tfar = std::min(static_cast<float>(1.0 - offset / length), std::nextafter(1.0f, 0.0f));
  }
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
  return true;
}

// Embree sets tfar to -inf on a hit.
double lit_after(float tfar) { return tfar >= 0.0f ? 1.0 : 0.0; }

// Casts rays[i] for every i in packets of W (Packet: RTCRayW; occluded: rtcOccludedW), the
// last one padded with invalid lanes, and writes lit_after(tfar) of ray i to out[i].
template <int W, typename Packet>
void cast_in_packets(RTCScene scene, std::span<const RTCRay> rays, std::span<double> out,
                     void (*occluded)(const int*, RTCScene, RTCIntersectContext*, Packet*)) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  for (std::size_t first = 0; first < rays.size(); first += W) {
    const std::size_t n = std::min<std::size_t>(W, rays.size() - first);
    alignas(64) int valid[W];
    Packet packet;
    for (std::size_t i = 0; i < W; ++i) {
      // Invalid lanes repeat the last ray: well-formed values Embree does not look at.
      const RTCRay& ray = rays[first + std::min(i, n - 1)];
      valid[i] = i < n ? -1 : 0;
      packet.org_x[i] = ray.org_x;
      packet.org_y[i] = ray.org_y;
      packet.org_z[i] = ray.org_z;
      packet.dir_x[i] = ray.dir_x;
      packet.dir_y[i] = ray.dir_y;
      packet.dir_z[i] = ray.dir_z;
      packet.tnear[i] = ray.tnear;
      packet.tfar[i] = ray.tfar;
      packet.time[i] = ray.time;
      packet.mask[i] = ray.mask;
      packet.id[i] = ray.id;
      packet.flags[i] = ray.flags;
    }
    occluded(valid, scene, &context, &packet);
    for (std::size_t i = 0; i < n; ++i) out[first + i] = lit_after(packet.tfar[i]);
  }
}

}  // namespace

RayCaster::RayCaster(RTCDevice device, std::span<const Triangle3> occluders) {
  // Stored as they are (centre 0): the offset below is relative to the scene's own
  // coordinates.
  const EmbreeTriangles built = embree_triangles(device, occluders, glm::dvec3(0.0));
  scene_ = built.scene;
  offset_ = kOffsetUlps * 0x1.0p-23 * built.magnitude;
  packet_width_ = native_packet_width(device);
}

RayCaster::~RayCaster() { rtcReleaseScene(scene_); }

double RayCaster::lit(const Light& light, const glm::dvec3& point, const glm::dvec3& normal) const {
  RTCRay ray;
  if (!shadow_ray(light, point, normal, offset_, ray)) return 1.0;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(scene_, &context, &ray);
  return lit_after(ray.tfar);
}

void RayCaster::lit(const Light& light, std::span<const glm::dvec3> points,
                    std::span<const glm::dvec3> normals, std::span<double> out,
                    Casting casting) const {
  if (normals.size() != points.size() || out.size() != points.size()) {
    throw std::invalid_argument("RayCaster::lit: points, normals and out differ in size");
  }
  if (casting == Casting::kOneByOne || packet_width_ == 1) {
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = lit(light, points[i], normals[i]);
    return;
  }
  // The rays to cast, and the points they start from; the others are lit without one.
  thread_local std::vector<RTCRay> rays;
  thread_local std::vector<std::size_t> from;
  thread_local std::vector<double> answers;
  rays.clear();
  from.clear();
  for (std::size_t i = 0; i < points.size(); ++i) {
    RTCRay ray;
    if (shadow_ray(light, points[i], normals[i], offset_, ray)) {
      rays.push_back(ray);
      from.push_back(i);
    } else {
      out[i] = 1.0;
    }
  }
  answers.resize(rays.size());
  switch (packet_width_) {
    case 16:
      cast_in_packets<16>(scene_, rays, answers, &rtcOccluded16);
      break;
    case 8:
      cast_in_packets<8>(scene_, rays, answers, &rtcOccluded8);
      break;
    default:
      cast_in_packets<4>(scene_, rays, answers, &rtcOccluded4);
      break;
  }
  for (std::size_t j = 0; j < from.size(); ++j) out[from[j]] = answers[j];
}

}  // namespace shadowgen::sampled
