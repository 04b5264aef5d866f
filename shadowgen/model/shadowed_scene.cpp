#include "shadowgen/model/shadowed_scene.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "hsr/area.h"
#include "shadowgen/model/input_error.h"
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

void check_lit_shape(const ShadowedScene& shadowed, std::string_view who) {
  const Scene& scene = shadowed.scene;
  if (shadowed.lit.size() != scene.faces.size() || shadowed.lit.lights() != scene.lights.size()) {
    throw std::invalid_argument(
        std::string(who) + ": lit polygons for " + std::to_string(shadowed.lit.size()) +
        " faces and " + std::to_string(shadowed.lit.lights()) + " lights, the scene has " +
        std::to_string(scene.faces.size()) + " and " + std::to_string(scene.lights.size()));
  }
}

LitAreas::LitAreas(const ShadowedScene& shadowed)
    : shadowed_(shadowed), place_(shadowed.scene.lights.size()) {
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
  if (!shadowed_.method.exact()) return shadowed_.estimated_lit_area.at(light).at(face);
  return lit_area(shadowed_.lit.at(face, light));
}

}  // namespace shadowgen
