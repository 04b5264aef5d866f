#include "shadowgen/sampled/embree_triangles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace shadowgen::sampled {

void check_embree(RTCDevice device, const char* what) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(error)) + ")");
  }
}

EmbreeTriangles embree_triangles(RTCDevice device, std::span<const Triangle3> triangles,
                                 const glm::dvec3& centre, RTCFilterFunctionN filter) {
  EmbreeTriangles out;
  out.scene = rtcNewScene(device);
  if (out.scene == nullptr) {
    check_embree(device, "making a scene");
    throw std::runtime_error("embree: making a scene failed");
  }
  rtcSetSceneFlags(out.scene, RTC_SCENE_FLAG_ROBUST);
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
      rtcReleaseScene(out.scene);
      check_embree(device, "geometry buffers");
      throw std::runtime_error("embree: geometry buffers failed");
    }
    unsigned next = 0;
    for (const Triangle3& t : triangles) {
      for (const glm::dvec3* v : {&t.a, &t.b, &t.c}) {
        const glm::dvec3 p = *v - centre;
        out.magnitude = std::max({out.magnitude, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
        *xyz++ = static_cast<float>(p.x);
        *xyz++ = static_cast<float>(p.y);
        *xyz++ = static_cast<float>(p.z);
        *index++ = next++;
      }
    }
    if (filter != nullptr) rtcSetGeometryIntersectFilterFunction(geometry, filter);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(out.scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(out.scene);
  try {
    check_embree(device, "building the hierarchy");
  } catch (...) {
    rtcReleaseScene(out.scene);
    throw;
  }
  return out;
}

}  // namespace shadowgen::sampled
