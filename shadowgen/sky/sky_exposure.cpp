#include "shadowgen/sky/sky_exposure.h"

#include <cstring>
#include <glm/geometric.hpp>
#include <numbers>
#include <numeric>
#include <unordered_map>

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

// How far in front of a part's plane (the sine of the angle) a patch's centre must lie for
// the part's lit area under the patch's light to count: a centre within it, in the plane
// but for rounding, may have lit the part or not; the part then counts as unobstructed.
constexpr double kCentreInFrontOfPlane = 1e-9;

}  // namespace

SkyExposure sky_exposure(const Scene& scene, const SkyOptions& options) {
  SkyExposure out;
  out.patches = reinhart_patches(options.subdivisions);
  GenerateOptions generate;
  generate.threads = options.threads;
  generate.sun_hours_regions = false;
  generate.on_light_done = options.on_light_done;
  const GenerateResult result = generate_shadows(sky_scene(scene, out.patches), generate);
  const SunPathHours& path = result.shadowed.sun_paths.at(0);
  const double north_axis_deg = scene.site ? scene.site->north_axis_deg : 0.0;
  CosineIntegrals integrals(out.patches);
  const std::size_t faces = scene.faces.size(), patches = out.patches.size();
  out.area.assign(faces, 0.0);
  out.ground_view_factor.assign(faces, 0.0);
  out.lit_weight.assign(faces, std::vector<double>(patches, 0.0));
  out.open_weight.assign(faces, std::vector<double>(patches, 0.0));
  for (std::size_t f = 0; f < faces; ++f) {
    const Face& face = scene.faces[f];
    for (const hsr::Polygon3& part : face.parts) out.area[f] += hsr::area(part);
    if (out.area[f] <= 0.0) continue;
    for (std::size_t i = 0; i < face.parts.size(); ++i) {
      const double part_area = hsr::area(face.parts[i]);
      const glm::dvec3 newell = hsr::newell_vector(face.parts[i].outer);
      const double length = glm::length(newell);
      if (part_area <= 0.0 || length <= 0.0) continue;
      const glm::dvec3 normal = sky_from_scene(newell / length, north_axis_deg);
      out.ground_view_factor[f] += part_area * (1.0 - normal.z) / 2.0 / out.area[f];
      const std::vector<double>& cosine = integrals.of(normal);
      for (std::size_t p = 0; p < patches; ++p) {
        if (cosine[p] <= 0.0) continue;
        const bool faces_centre = glm::dot(normal, out.patches[p].centre) > kCentreInFrontOfPlane;
        const double lit = faces_centre ? part_lit_area(path, f, i, p) : part_area;
        out.lit_weight[f][p] += std::min(lit, part_area) * cosine[p] / out.area[f];
        out.open_weight[f][p] += part_area * cosine[p] / out.area[f];
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
