#include "shadowgen/sampled/estimate.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "hsr/parallel.h"
#include "hsr/polygon3.h"
#include "shadowgen/sampled/face_samples.h"
#include "shadowgen/sampled/part_triangles.h"
#include "shadowgen/sampled/ray_caster.h"
#include "shadowgen/sampled/shadow_map.h"
#include "shadowgen/shadows/light_scope.h"

namespace shadowgen::sampled {
namespace {

void check_method(const Method& method) {
  if (method.kind != MethodKind::kRays && method.kind != MethodKind::kShadowMap) {
    throw std::invalid_argument("sampled estimate: the method must be rays or shadow-map, not " +
                                std::string(method_name(method.kind)));
  }
  if (method.samples < 1 || method.samples > kMaxSamples) {
    throw std::invalid_argument("sampled estimate: samples per face must be 1 to " +
                                std::to_string(kMaxSamples) + ", not " +
                                std::to_string(method.samples));
  }
  // A ray needs no map: the resolution is the shadow map's alone.
  if (method.kind == MethodKind::kShadowMap &&
      (method.resolution < 1 || method.resolution > kMaxResolution)) {
    throw std::invalid_argument("sampled estimate: the shadow map's resolution must be 1 to " +
                                std::to_string(kMaxResolution) + ", not " +
                                std::to_string(method.resolution));
  }
}

}  // namespace

struct Estimator::Impl {
  const Scene& scene;
  Method method;
  // Every part of every face, face by face: what the light's scope is decided on
  // (light_scope.h), and each part's triangles, in the same order.
  ScenePartPlanes all;
  std::vector<PartTriangles> parts;
  // Rays: one Embree device for every light (its thread pool and settings), and the
  // hierarchy over every part, built at the first light that leaves no part out (a sun,
  // a point light without range, or one whose range takes in the whole scene) and shared
  // by all such lights.
  RTCDevice device = nullptr;
  // A face's rays go to Embree in packets: the same answers as one by one, faster
  // (ray_caster.h); set_casting changes it.
  Casting casting = Casting::kPackets;
  std::once_flag whole_once;
  std::unique_ptr<RayCaster> whole;

  Impl(const Scene& s, const Method& m) : scene(s), method(m), all(s) {
    for (const Face& face : scene.faces) {
      for (const hsr::Polygon3& part : face.parts) {
        try {
          parts.push_back(part_triangles(part));
        } catch (const std::runtime_error& e) {
          throw std::runtime_error("face " + face.id + ": " + e.what());
        }
      }
    }
    if (method.kind == MethodKind::kRays) {
      device = rtcNewDevice(nullptr);
      if (device == nullptr) throw std::runtime_error("embree: no device");
    }
  }
  ~Impl() {
    whole.reset();
    if (device != nullptr) rtcReleaseDevice(device);
  }

  std::vector<Triangle3> occluders(const std::vector<PartRole>& roles) const {
    std::vector<Triangle3> triangles;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (occludes(roles[i])) {
        triangles.insert(triangles.end(), parts[i].triangles.begin(), parts[i].triangles.end());
      }
    }
    return triangles;
  }

  // Every face's part estimates, `lit(face, points, normals, out)` the lit fractions of a
  // face's sample points on parts facing the light, `face` the triangles of those parts
  // for a shadow map, empty for rays (called from several threads at once). Faces are independent:
  // in parallel, the same numbers on any number of threads.
  template <typename Lit>
  PartLitAreas estimate(const std::vector<PartRole>& roles, Lit lit) const {
    PartLitAreas areas(scene.faces.size());
    hsr::for_each_in_parallel(scene.faces.size(), [&](std::size_t f) {
      const std::size_t first = all.first[f];
      const std::span<const PartTriangles> face(parts.data() + first, all.first[f + 1] - first);
      const auto role = [&](std::size_t k) { return roles[first + k]; };
      bool any = false;
      for (std::size_t k = 0; k < face.size(); ++k) any = any || role(k) == PartRole::kFacing;
      if (!any) {
        areas[f].assign(face.size(), 0.0);
        return;
      }
      thread_local std::vector<FaceSample> samples;
      thread_local std::vector<glm::dvec3> points, normals;
      thread_local std::vector<std::size_t> which;
      thread_local std::vector<double> decided, fraction;
      thread_local std::vector<Triangle3> facing;
      face_samples(face, method.samples, f, samples);
      facing.clear();
      // The shadow map looks a face up as a whole (ShadowMap::lit_face); rays need no more
      // than the points.
      for (std::size_t k = 0; method.kind == MethodKind::kShadowMap && k < face.size(); ++k) {
        if (role(k) != PartRole::kFacing) continue;
        facing.insert(facing.end(), face[k].triangles.begin(), face[k].triangles.end());
      }
      points.clear();
      normals.clear();
      which.clear();
      for (std::size_t i = 0; i < samples.size(); ++i) {
        const std::size_t k = samples[i].part;
        if (role(k) != PartRole::kFacing) continue;
        points.push_back(samples[i].point);
        normals.push_back(face[k].normal);
        which.push_back(i);
      }
      decided.resize(points.size());
      lit(std::span<const Triangle3>(facing), std::span<const glm::dvec3>(points),
          std::span<const glm::dvec3>(normals), std::span<double>(decided));
      fraction.assign(samples.size(), 0.0);
      for (std::size_t j = 0; j < which.size(); ++j) fraction[which[j]] = decided[j];
      areas[f] = part_lit_areas(face, samples, fraction);
    });
    return areas;
  }
};

Estimator::Estimator(const Scene& scene, const Method& method) {
  check_method(method);
  impl_ = std::make_unique<Impl>(scene, method);
}

Estimator::~Estimator() = default;

const Method& Estimator::method() const { return impl_->method; }

PartLitAreas Estimator::lit_areas(const Light& light) const {
  Impl& impl = *impl_;
  const std::vector<PartRole> roles = part_roles(impl.all.polygons, impl.all.planes, light);
  if (impl.method.kind == MethodKind::kShadowMap) {
    const ShadowMap map(light, impl.occluders(roles), impl.method.resolution);
    return impl.estimate(roles,
                         [&](std::span<const Triangle3> face, std::span<const glm::dvec3> points,
                             std::span<const glm::dvec3> normals,
                             std::span<double> out) { map.lit_face(face, points, normals, out); });
  }
  const bool everything = std::all_of(roles.begin(), roles.end(), occludes);
  std::optional<RayCaster> own;
  const RayCaster* caster = nullptr;
  if (everything) {
    std::call_once(impl.whole_once, [&] {
      impl.whole = std::make_unique<RayCaster>(impl.device, impl.occluders(roles));
    });
    caster = impl.whole.get();
  } else {
    caster = &own.emplace(impl.device, impl.occluders(roles));
  }
  return impl.estimate(roles, [&](std::span<const Triangle3>, std::span<const glm::dvec3> points,
                                  std::span<const glm::dvec3> normals, std::span<double> out) {
    caster->lit(light, points, normals, out, impl.casting);
  });
}

void set_casting(Estimator& estimator, Casting casting) { estimator.impl_->casting = casting; }

}  // namespace shadowgen::sampled
