#include "shadowgen/sky/sky_exposure.h"

#include <cstring>
#include <glm/geometric.hpp>
#include <numbers>
#include <numeric>
#include <unordered_map>
#include <utility>

#include "hsr/area.h"
#include "hsr/polygon3.h"
#include "shadowgen/sky/patch_cosine.h"
#include "shadowgen/sky/sky_lights.h"

namespace shadowgen::sky {
namespace {

// I(n, p) for every patch, once per distinct normal (a district's walls and roofs share a
// few).
class CosineIntegrals {
 public:
  explicit CosineIntegrals(const std::vector<SkyPatch>& patches) : patches_(patches) {}

  const std::vector<double>& of(const glm::dvec3& normal) {
    Key key;
    std::memcpy(key.bits, &normal[0], sizeof key.bits);
    auto [at, added] = cache_.try_emplace(key);
    if (added) {
      at->second.reserve(patches_.size());
      for (const SkyPatch& p : patches_) at->second.push_back(patch_cosine_integral(p, normal));
    }
    return at->second;
  }

 private:
  struct Key {
    unsigned char bits[3 * sizeof(double)];
    bool operator==(const Key& other) const {
      return std::memcmp(bits, other.bits, sizeof bits) == 0;
    }
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = 1469598103934665603ull;
      for (const unsigned char b : k.bits) h = (h ^ b) * 1099511628211ull;
      return h;
    }
  };
  const std::vector<SkyPatch>& patches_;
  std::unordered_map<Key, std::vector<double>, KeyHash> cache_;
};

}  // namespace

std::vector<SkyPart> sky_parts(const Face& face, double north_axis_deg) {
  std::vector<SkyPart> out;
  out.reserve(face.parts.size());
  for (const hsr::Polygon3& polygon : face.parts) {
    SkyPart part;
    part.area = hsr::area(polygon);
    const glm::dvec3 newell = hsr::newell_vector(polygon.outer);
    const double length = glm::length(newell);
    if (part.area > 0.0 && length > 0.0) {
      part.normal = sky_from_scene(newell / length, north_axis_deg);
      part.oriented = true;
    }
    out.push_back(part);
  }
  return out;
}

double sky_lit_area(const SunPathHours& path, std::size_t f, std::size_t i, const SkyPart& part,
                    std::size_t k, const glm::dvec3& centre) {
  if (glm::dot(part.normal, centre) <= kCentreInFrontOfPlane) return part.area;
  return std::min(part_lit_area(path, f, i, k), part.area);
}

SunPathHours sky_lit_areas(const Scene& scene, const std::vector<SkyPatch>& patches,
                           const SkyOptions& options) {
  GenerateOptions generate;
  generate.threads = options.threads;
  generate.sun_hours_regions = false;
  generate.on_light_done = options.on_light_done;
  GenerateResult result = generate_shadows(sky_scene(scene, patches), generate);
  return std::move(result.shadowed.sun_paths.at(0));
}

SkyExposure sky_exposure(const Scene& scene, const SkyOptions& options) {
  std::vector<SkyPatch> patches = reinhart_patches(options.subdivisions);
  const SunPathHours path = sky_lit_areas(scene, patches, options);
  return sky_exposure_of(scene, path, 0, std::move(patches));
}

SkyExposure sky_exposure_of(const Scene& scene, const SunPathHours& path, std::size_t first,
                            std::vector<SkyPatch> patches_lit) {
  SkyExposure out;
  out.patches = std::move(patches_lit);
  const double north_axis_deg = scene.site ? scene.site->north_axis_deg : 0.0;
  CosineIntegrals integrals(out.patches);
  const std::size_t faces = scene.faces.size(), patches = out.patches.size();
  out.area.assign(faces, 0.0);
  out.ground_view_factor.assign(faces, 0.0);
  out.lit_weight.assign(faces, std::vector<double>(patches, 0.0));
  out.open_weight.assign(faces, std::vector<double>(patches, 0.0));
  for (std::size_t f = 0; f < faces; ++f) {
    const std::vector<SkyPart> parts = sky_parts(scene.faces[f], north_axis_deg);
    for (const SkyPart& part : parts) out.area[f] += part.area;
    if (out.area[f] <= 0.0) continue;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const SkyPart& part = parts[i];
      if (!part.oriented) continue;
      out.ground_view_factor[f] += part.area * (1.0 - part.normal.z) / 2.0 / out.area[f];
      const std::vector<double>& cosine = integrals.of(part.normal);
      for (std::size_t p = 0; p < patches; ++p) {
        if (cosine[p] <= 0.0) continue;
        const double lit = sky_lit_area(path, f, i, part, first + p, out.patches[p].centre);
        out.lit_weight[f][p] += lit * cosine[p] / out.area[f];
        out.open_weight[f][p] += part.area * cosine[p] / out.area[f];
      }
    }
  }
  return out;
}

double sky_view_factor(const SkyExposure& exposure, std::size_t face) {
  const std::vector<double>& w = exposure.lit_weight.at(face);
  return std::accumulate(w.begin(), w.end(), 0.0) / std::numbers::pi;
}

}  // namespace shadowgen::sky
