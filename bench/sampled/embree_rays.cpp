#include "bench/sampled/embree_rays.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <string>

#include "bench/sampled/light_scope.h"
#include "bench/sampled/stratified_samples.h"

namespace shadowgen::bench {
namespace {

// How far a ray starts off its face, along the face's normal towards the light, in units
// of the float spacing (2^-23 of the face's largest coordinate magnitude m). Embree works
// in single precision: rounding the face's vertices and the ray's origin to floats moves
// each by at most half a unit per coordinate, so the origin may end up up to about 1.7
// units behind the rounded plane, and Embree's own intersection arithmetic adds a few
// more; 8 units clears both, so a ray never hits its own face. The offset is kept that
// small on purpose: a ray leaving a face at a grazing angle θ passes an occluder next to
// it (a neighbour across a concave edge) higher by offset / sin θ: an offset of 1e-5 of
// the scene misses shadows near the terminator and lights some faces of the benchmark's
// meshes up to 25 % more than the exact result and double-precision rays both say.
constexpr double kOffsetUlps = 8.0;

double origin_offset(const std::vector<glm::dvec3>& loop) {
  double m = 0.0;
  for (const glm::dvec3& v : loop) {
    m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  }
  return kOffsetUlps * 0x1.0p-23 * m;
}

void check(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(error)) + ")");
  }
}

class EmbreeScene {
 public:
  EmbreeScene(RTCDevice device, const LightScope& scope) : scene_(rtcNewScene(device)) {
    std::size_t vertices = 0, triangles = 0;
    for (std::size_t f = 0; f < scope.faces.size(); ++f) {
      if (!scope.present[f]) continue;
      vertices += scope.faces[f].loop.size();
      triangles += scope.faces[f].loop.size() - 2;
    }
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* xyz = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices));
    auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles));
    check(device, "geometry buffers");
    unsigned base = 0;
    for (std::size_t f = 0; f < scope.faces.size(); ++f) {
      if (!scope.present[f]) continue;
      const std::vector<glm::dvec3>& loop = scope.faces[f].loop;
      for (const glm::dvec3& v : loop) {
        *xyz++ = static_cast<float>(v.x);
        *xyz++ = static_cast<float>(v.y);
        *xyz++ = static_cast<float>(v.z);
      }
      for (unsigned i = 1; i + 1 < loop.size(); ++i) {
        *index++ = base;
        *index++ = base + i;
        *index++ = base + i + 1;
      }
      base += static_cast<unsigned>(loop.size());
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
    check(device, "building the hierarchy");
  }
  ~EmbreeScene() { rtcReleaseScene(scene_); }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // How many of the rays from `origins` towards `light` (t in [0, tfar] along the
  // unnormalised direction) reach it unblocked.
  std::size_t unoccluded(const std::vector<glm::dvec3>& origins, const Light& light, float tfar,
                         RayCasting casting) const {
    return casting == RayCasting::kOneByOne ? one_by_one(origins, light, tfar)
                                            : in_packets(origins, light, tfar);
  }

 private:
  std::size_t one_by_one(const std::vector<glm::dvec3>& origins, const Light& light,
                         float tfar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    std::size_t reached = 0;
    for (const glm::dvec3& o : origins) {
      const glm::dvec3 d = towards_light(light, o);
      RTCRay ray;
      ray.org_x = static_cast<float>(o.x);
      ray.org_y = static_cast<float>(o.y);
      ray.org_z = static_cast<float>(o.z);
      ray.dir_x = static_cast<float>(d.x);
      ray.dir_y = static_cast<float>(d.y);
      ray.dir_z = static_cast<float>(d.z);
      ray.tnear = 0.0f;
      ray.tfar = tfar;
      ray.time = 0.0f;
      ray.mask = std::numeric_limits<unsigned>::max();
      ray.id = 0;
      ray.flags = 0;
      rtcOccluded1(scene_, &context, &ray);
      if (ray.tfar >= 0.0f) ++reached;  // Embree sets tfar to -inf on a hit
    }
    return reached;
  }

  // The rays of one face start close together and head the same way: Embree traverses
  // such a packet once for all 16, the coherent case packets are made for.
  std::size_t in_packets(const std::vector<glm::dvec3>& origins, const Light& light,
                         float tfar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    std::size_t reached = 0;
    for (std::size_t first = 0; first < origins.size(); first += 16) {
      alignas(64) int valid[16];
      RTCRay16 ray;
      for (std::size_t i = 0; i < 16; ++i) {
        const std::size_t r = std::min(first + i, origins.size() - 1);
        valid[i] = first + i < origins.size() ? -1 : 0;
        const glm::dvec3& o = origins[r];
        const glm::dvec3 d = towards_light(light, o);
        ray.org_x[i] = static_cast<float>(o.x);
        ray.org_y[i] = static_cast<float>(o.y);
        ray.org_z[i] = static_cast<float>(o.z);
        ray.dir_x[i] = static_cast<float>(d.x);
        ray.dir_y[i] = static_cast<float>(d.y);
        ray.dir_z[i] = static_cast<float>(d.z);
        ray.tnear[i] = 0.0f;
        ray.tfar[i] = tfar;
        ray.time[i] = 0.0f;
        ray.mask[i] = std::numeric_limits<unsigned>::max();
        ray.id[i] = 0;
        ray.flags[i] = 0;
      }
      rtcOccluded16(valid, scene_, &context, &ray);
      for (std::size_t i = 0; i < 16; ++i) {
        if (valid[i] && ray.tfar[i] >= 0.0f) ++reached;
      }
    }
    return reached;
  }

  RTCScene scene_;
};

}  // namespace

EmbreeShadowRays::EmbreeShadowRays() : device_(rtcNewDevice("threads=1,set_affinity=0")) {
  if (device_ == nullptr) throw std::runtime_error("embree: no device");
}

EmbreeShadowRays::~EmbreeShadowRays() { rtcReleaseDevice(device_); }

std::vector<double> EmbreeShadowRays::lit_areas(const Scene& scene, const Light& light, int k,
                                                RayCasting casting) const {
  const LightScope scope = light_scope(scene, light);
  const EmbreeScene rays(device_, scope);
  // A point light is reached at t = 1 along the unnormalised direction to it.
  const float tfar =
      light.type == LightType::kDirectional ? std::numeric_limits<float>::infinity() : 1.0f;
  std::vector<double> areas(scope.faces.size(), 0.0);
  std::vector<glm::dvec3> samples;
  for (std::size_t f = 0; f < scope.faces.size(); ++f) {
    if (!scope.receives[f]) continue;
    const ConvexFace& face = scope.faces[f];
    stratified_samples(face.loop, k, samples);
    if (samples.empty()) continue;
    const glm::dvec3 lift = origin_offset(face.loop) * face.normal;
    for (glm::dvec3& p : samples) p += lift;
    const std::size_t lit = rays.unoccluded(samples, light, tfar, casting);
    areas[f] = face.area * static_cast<double>(lit) / static_cast<double>(samples.size());
  }
  return areas;
}

}  // namespace shadowgen::bench
