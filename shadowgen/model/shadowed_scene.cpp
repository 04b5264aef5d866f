#include "shadowgen/model/shadowed_scene.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hsr/area.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/keep_marked.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen {

namespace {

// `known`: the ids of the sun paths there are, in order.
[[noreturn]] void throw_no_sun_path(std::string_view id, const std::vector<std::string>& known,
                                    const std::string& file) {
  std::string list;
  for (const std::string& k : known) list += (list.empty() ? "'" : ", '") + one_line(k) + "'";
  throw InputError(file, "",
                   list.empty()
                       ? "has no sun path (a `sun` light with from, to and step_min), "
                         "so no sun hours of '" +
                             one_line(id) + "'"
                       : "has no sun path '" + one_line(id) + "' (its sun paths: " + list + ")");
}

}  // namespace

const SunPathHours& sun_path_named(const ShadowedScene& shadowed, std::string_view id,
                                   const std::string& file) {
  std::vector<std::string> known;
  for (const SunPathHours& path : shadowed.sun_paths) {
    if (path.id == id) return path;
    known.push_back(path.id);
  }
  throw_no_sun_path(id, known, file);
}

void require_sun_path(const Scene& scene, std::string_view id, const std::string& file) {
  std::vector<std::string> known;
  for (const SunPathSpan& path : scene.sun_paths) {
    if (path.id == id) return;  // with or without an instant
    known.push_back(path.id);
  }
  for (const Light& light : scene.lights) {
    if (!light.sun || light.sun->step_min == 0) continue;  // not an instant of a path
    if (light.sun->sun_id == id) return;
    if (std::find(known.begin(), known.end(), light.sun->sun_id) == known.end()) {
      known.push_back(light.sun->sun_id);
    }
  }
  throw_no_sun_path(id, known, file);
}

void require_regions(const SunPathHours& path, const std::string& file, std::string_view what) {
  if (path.regions_kept) return;
  throw InputError(file, "",
                   "sun path '" + one_line(path.id) +
                       "' was summed into lit areas alone (generate --areas-only), without the "
                       "sun-hours regions " +
                       std::string(what) + " needs: generate without --areas-only");
}

double lit_area(std::span<const LitPolygon> lit) {
  double sum = 0.0;
  for (const LitPolygon& p : lit) sum += hsr::area(p.polygon);
  return sum;
}

std::vector<hsr::Polygon3> polygons_of(std::span<const LitPolygon> lit) {
  std::vector<hsr::Polygon3> out;
  out.reserve(lit.size());
  for (const LitPolygon& p : lit) out.push_back(p.polygon);
  return out;
}

std::vector<hsr::Polygon3> polygons_on_part(std::span<const LitPolygon> lit, std::size_t part) {
  std::vector<hsr::Polygon3> out;
  for (const LitPolygon& p : lit) {
    if (p.part == part) out.push_back(p.polygon);
  }
  return out;
}

double part_lit_area(const SunPathHours& path, std::size_t face, std::size_t part, std::size_t k) {
  const std::vector<std::vector<double>>& parts = path.part_lit_area.at(face);
  if (parts.empty()) {
    if (part != 0) throw std::out_of_range("part_lit_area: a face of one part");
    return path.lit_area.at(face).at(k);
  }
  return parts.at(part).at(k);
}

ShadowedScene::ShadowedScene(Scene scene, LitTable lit)
    : scene_(std::move(scene)), lit_(std::move(lit)) {
  check();
}

ShadowedScene::ShadowedScene(Scene scene, LitTable lit, Estimate estimate)
    : scene_(std::move(scene)), lit_(std::move(lit)), estimate_(std::move(estimate)) {
  check();
}

void ShadowedScene::check() const {
  const std::size_t faces = scene_.faces.size(), lights = scene_.lights.size();
  if (lit_.size() != faces || lit_.lights() != lights) {
    throw std::invalid_argument("ShadowedScene: lit polygons for " + std::to_string(lit_.size()) +
                                " faces and " + std::to_string(lit_.lights()) +
                                " lights, the scene has " + std::to_string(faces) + " and " +
                                std::to_string(lights));
  }
  if (!estimate_) return;
  if (estimate_->method.exact()) {
    throw std::invalid_argument("ShadowedScene: an estimate by the exact method");
  }
  if (estimate_->lit_area.size() != lights) {
    throw std::invalid_argument("ShadowedScene: estimated lit areas for " +
                                std::to_string(estimate_->lit_area.size()) +
                                " lights, the scene has " + std::to_string(lights));
  }
  for (std::size_t l = 0; l < lights; ++l) {
    const Light& light = scene_.lights[l];
    if (lit_.kept(l)) {
      throw std::invalid_argument("ShadowedScene: an estimate with lit polygons for light '" +
                                  one_line(light.id) + "'");
    }
    const std::size_t given = estimate_->lit_area[l].size();
    if (given != faces && !(given == 0 && in_sun_path(light))) {
      throw std::invalid_argument("ShadowedScene: estimated lit areas of " + std::to_string(given) +
                                  " faces for light '" + one_line(light.id) + "', the scene has " +
                                  std::to_string(faces));
    }
  }
}

void ShadowedScene::add_face(Face face, const std::vector<std::optional<double>>& estimated) {
  const std::size_t lights = scene_.lights.size();
  if (estimate_ ? estimated.size() != lights : !estimated.empty()) {
    throw std::invalid_argument("ShadowedScene::add_face: estimated lit areas for " +
                                std::to_string(estimated.size()) + " lights, " +
                                std::to_string(estimate_ ? lights : 0) + " wanted");
  }
  const std::size_t faces = scene_.faces.size();
  for (std::size_t l = 0; l < estimated.size(); ++l) {
    if (estimate_->lit_area[l].size() != (estimated[l] ? faces : 0)) {
      throw std::invalid_argument(
          "ShadowedScene::add_face: light '" + one_line(scene_.lights[l].id) + "' " +
          (estimated[l] ? "has" : "lacks") + " an estimated lit area, unlike the faces before");
    }
  }
  scene_.faces.push_back(std::move(face));
  lit_.add_face();
  for (std::size_t l = 0; l < estimated.size(); ++l) {
    if (estimated[l]) estimate_->lit_area[l].push_back(*estimated[l]);
  }
  check();
}

void ShadowedScene::keep_lights(const std::vector<bool>& keep) {
  if (keep.size() != scene_.lights.size()) {
    throw std::invalid_argument("ShadowedScene::keep_lights: " + std::to_string(keep.size()) +
                                " flags for " + std::to_string(scene_.lights.size()) + " lights");
  }
  keep_marked(scene_.lights, keep);
  lit_.keep_lights(keep);
  if (estimate_) keep_marked(estimate_->lit_area, keep);
}

LitAreas::LitAreas(const ShadowedScene& shadowed)
    : shadowed_(shadowed), place_(shadowed.scene().lights.size()) {
  for (const SunPathHours& path : shadowed.sun_paths) {
    if (path.lit_polygons_kept) continue;
    for (std::size_t k = 0; k < path.instants.size(); ++k) {
      place_.at(path.instants[k]) = Place{&path, k};
    }
  }
}

double LitAreas::operator()(std::size_t face, std::size_t light) const {
  const Place& place = place_.at(light);
  if (place.path) return place.path->lit_area.at(face).at(place.instant);
  if (const std::optional<Estimate>& estimate = shadowed_.estimate()) {
    return estimate->lit_area.at(light).at(face);
  }
  return lit_area(shadowed_.lit().at(face, light));
}

}  // namespace shadowgen
