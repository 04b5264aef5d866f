#include "shadowgen/view/render.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "detail/painter.h"
#include "shadowgen/shadows/light_regions.h"
#include "shadowgen/view/light_set_legend.h"

namespace shadowgen {
namespace {

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

// Faces split by their light-set regions (shadowgen/shadows/light_regions.h), each piece
// shaded by the lights of its set; the shadow gets what the lit regions leave.
class LightSetTiling : public view::detail::FaceTiling {
 public:
  LightSetTiling(const ShadowedScene& shadowed, const RenderOptions& options)
      : shadowed_(shadowed), options_(options) {}

  void load(std::size_t face) override {
    regions_ = light_regions(shadowed_, face);
    rest_ = view::detail::kNoRegion;
    for (std::size_t r = 0; r < regions_.size(); ++r) {
      if (regions_[r].lights.empty()) rest_ = r;
    }
  }
  std::size_t size() const override { return regions_.size(); }
  std::span<const LitPolygon> polygons(std::size_t region) const override {
    return regions_[region].polygons;
  }
  std::size_t rest() const override { return rest_; }

  void style(Piece& piece, std::size_t region, const glm::dvec3& centroid,
             const glm::dvec3& normal) const override {
    const Scene& scene = shadowed_.scene();
    piece.face_id = scene.faces[piece.face].id;
    if (region != view::detail::kNoRegion) piece.lights = regions_[region].lights;
    piece.light_set = light_set_name(scene, piece.lights);
    piece.colour = shade(scene, piece.lights, centroid, normal, options_);
  }

 private:
  const ShadowedScene& shadowed_;
  const RenderOptions& options_;
  std::vector<LightRegion> regions_;
  std::size_t rest_ = view::detail::kNoRegion;
};

// Each light's lit polygons a layer over the face in shadow, coloured by that light's
// term of the shading formula alone.
class LightLayerTiling : public view::detail::FaceTiling {
 public:
  LightLayerTiling(const ShadowedScene& shadowed, const RenderOptions& options)
      : shadowed_(shadowed), options_(options) {}

  void load(std::size_t face) override {
    lights_.clear();
    for (std::size_t l = 0; l < shadowed_.scene().lights.size(); ++l) {
      if (!shadowed_.lit().at(face, l).empty()) lights_.push_back(l);
    }
    face_ = face;
  }
  std::size_t size() const override { return lights_.size(); }
  std::span<const LitPolygon> polygons(std::size_t region) const override {
    return shadowed_.lit().at(face_, lights_[region]);
  }
  std::size_t rest() const override { return view::detail::kNoRegion; }
  bool layered() const override { return true; }

  void style(Piece& piece, std::size_t region, const glm::dvec3& centroid,
             const glm::dvec3& normal) const override {
    const Scene& scene = shadowed_.scene();
    piece.face_id = scene.faces[piece.face].id;
    const Rgb shadow = shade(scene, {}, centroid, normal, options_);
    if (region == view::detail::kNoRegion) {
      piece.light_set = light_set_name(scene, {});
      piece.colour = shadow;
      return;
    }
    piece.lights = {lights_[region]};
    piece.light_set = light_set_name(scene, piece.lights);
    piece.layer = 1 + lights_[region];
    const Rgb lit = shade(scene, piece.lights, centroid, normal, options_);
    piece.colour = {lit.r - shadow.r, lit.g - shadow.g, lit.b - shadow.b};
  }

 private:
  const ShadowedScene& shadowed_;
  const RenderOptions& options_;
  std::vector<std::size_t> lights_;  // the lights with lit polygons on the face
  std::size_t face_ = 0;
};

}  // namespace

namespace {

// Σ weight_L · intensity_L · max(0, n·l_L) · f_L over the lights `weight` gives a weight.
template <typename Weight>
Rgb shade_sum(const Scene& scene, std::size_t count, Weight weight, const glm::dvec3& point,
              const glm::dvec3& normal, const RenderOptions& options) {
  Rgb sum;
  for (std::size_t i = 0; i < count; ++i) {
    const auto [index, w] = weight(i);
    const Light& light = scene.lights.at(index);
    if (w == 0.0) continue;
    glm::dvec3 toward;
    double falloff = 1.0;
    if (light.type == LightType::kDirectional) {
      toward = -light.direction;
    } else {
      toward = light.position - point;
      const double d = glm::length(toward);
      if (light.range) {
        const LightRange& r = *light.range;
        if (d >= r.end) {
          falloff = 0.0;
        } else if (d > r.falloff_start) {
          falloff = std::pow(1.0 - (d - r.falloff_start) / (r.end - r.falloff_start), r.exponent);
        }
      }
    }
    const double length = glm::length(toward);
    if (!(length > 0.0)) continue;
    const double cosine = std::max(0.0, glm::dot(normal, toward) / length);
    const double k = w * cosine * falloff;
    sum.r += light.intensity.x * k;
    sum.g += light.intensity.y * k;
    sum.b += light.intensity.z * k;
  }
  const double weight_all =
      (1.0 - options.ambient) / static_cast<double>(std::max<std::size_t>(1, scene.lights.size()));
  return {clamp01(options.albedo.r * (options.ambient + weight_all * sum.r)),
          clamp01(options.albedo.g * (options.ambient + weight_all * sum.g)),
          clamp01(options.albedo.b * (options.ambient + weight_all * sum.b))};
}

}  // namespace

Rgb shade(const Scene& scene, const std::vector<std::size_t>& lights, const glm::dvec3& point,
          const glm::dvec3& normal, const RenderOptions& options) {
  return shade_sum(
      scene, lights.size(), [&](std::size_t i) { return std::pair(lights[i], 1.0); }, point, normal,
      options);
}

Rgb shade_weighted(const Scene& scene, std::span<const double> weights, const glm::dvec3& point,
                   const glm::dvec3& normal, const RenderOptions& options) {
  if (weights.size() != scene.lights.size()) {
    throw std::invalid_argument("shade_weighted: one weight per light of the scene is needed");
  }
  return shade_sum(
      scene, weights.size(), [&](std::size_t i) { return std::pair(i, weights[i]); }, point, normal,
      options);
}

Picture render(const ShadowedScene& shadowed, const Camera& camera, const RenderOptions& options) {
  LightSetTiling tiling(shadowed, options);
  Picture picture = view::detail::paint_picture(shadowed.scene(), camera, options, tiling);
  picture.legend = light_set_legend(picture.pieces);
  return picture;
}

Picture render_by_light(const ShadowedScene& shadowed, const Camera& camera,
                        const RenderOptions& options) {
  LightLayerTiling tiling(shadowed, options);
  Picture picture = view::detail::paint_picture(shadowed.scene(), camera, options, tiling);
  picture.layered = true;
  return picture;
}

}  // namespace shadowgen
