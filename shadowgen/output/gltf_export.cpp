#include "shadowgen/output/gltf_export.h"

#include <algorithm>
#include <cctype>
#include <glm/common.hpp>
#include <limits>
#include <map>
#include <stdexcept>
#include <vector>

#include "detail/gltf_model.h"
#include "detail/scene_regions.h"
#include "hsr/area.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/model/scene_centre.h"
#include "shadowgen/output/obj_export.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {
namespace {

using output::detail::GltfMaterial;
using output::detail::LightSet;

// What every export's scene extras hold: what it is, the origin, the site, the faces'
// ids and areas (the caller adds the rest).
nlohmann::json scene_extras(const Scene& scene, std::string_view kind, const glm::dvec3& origin) {
  nlohmann::json extras = {{"shadowgen", kind}, {"origin", {origin.x, origin.y, origin.z}}};
  if (scene.site) {
    const Site& site = *scene.site;
    extras["site"] = {{"latitude_deg", site.latitude_deg},
                      {"longitude_deg", site.longitude_deg},
                      {"elevation_m", site.elevation_m},
                      {"utc_offset_h", site.utc_offset_h},
                      {"north_axis_deg", site.north_axis_deg}};
  }
  std::vector<std::string> ids;
  std::vector<double> areas;
  ids.reserve(scene.faces.size());
  areas.reserve(scene.faces.size());
  for (const Face& face : scene.faces) {
    ids.push_back(face.id);
    areas.push_back(hsr::area(face.parts));
  }
  extras["faces"] = {{"id", std::move(ids)}, {"area", std::move(areas)}};
  return extras;
}

std::vector<std::string> light_ids(const Scene& scene, std::span<const std::size_t> lights) {
  std::vector<std::string> ids;
  for (const std::size_t l : lights) ids.push_back(scene.lights[l].id);
  return ids;
}

std::string as_is(std::string_view name) { return std::string(name); }

// Every face part's loops, each edge as a pair of points (GltfOptions::outlines); none
// unless asked for.
std::vector<glm::dvec3> outline_points(const Scene& scene, const GltfOptions& options) {
  std::vector<glm::dvec3> points;
  if (!options.outlines) return points;
  const auto add_loop = [&](const hsr::Loop3& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      points.push_back(loop[i]);
      points.push_back(loop[(i + 1) % loop.size()]);
    }
  };
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      add_loop(part.outer);
      for (const hsr::Loop3& hole : part.holes) add_loop(hole);
    }
  }
  return points;
}

}  // namespace

std::optional<GltfForm> gltf_form_of(std::string_view file_name) {
  const auto ends_with = [&](std::string_view suffix) {
    if (file_name.size() < suffix.size()) return false;
    return std::equal(
        suffix.begin(), suffix.end(), file_name.end() - suffix.size(),
        [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
  };
  if (ends_with(".glb")) return GltfForm::kBinary;
  if (ends_with(".gltf")) return GltfForm::kText;
  return std::nullopt;
}

std::string gltf_export(const ShadowedScene& shadowed, GltfForm form, const GltfOptions& options) {
  return light_set_gltf(shadowed, form, options).bytes;
}

LightSetGltf light_set_gltf(const ShadowedScene& shadowed, GltfForm form,
                            const GltfOptions& options) {
  const Scene& scene = shadowed.scene();
  const output::detail::SceneRegions regions = output::detail::scene_regions(shadowed);
  const output::detail::LightSetNames names =
      output::detail::light_set_names(scene, regions.sets, as_is);

  LightSetGltf out;
  std::vector<GltfMaterial> materials;
  std::map<LightSet, std::size_t, LightSetLess> material_of;
  for (const auto& [set, name] : names) {
    material_of.emplace(set, materials.size());
    materials.push_back(
        {name, light_set_colour(scene, set), {{"lights", light_ids(scene, set)}}, {}});
    out.materials.push_back({set, name});
  }

  std::vector<double> lit(scene.faces.size(), 0.0);
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (const LightRegion& region : regions.of_face[f]) {
      const double area = lit_area(region.polygons);
      if (!region.lights.empty()) lit[f] += area;
      if (!materials[material_of.at(region.lights)].mesh.add_piece(scene.faces[f], f,
                                                                   region.polygons, area)) {
        // Not the input's fault: valid regions always triangulate.
        throw GenerationError("", scene.faces[f].id, "",
                              "a region of light set '" + light_set_name(scene, region.lights) +
                                  "' could not be split into triangles");
      }
    }
  }

  const glm::dvec3 origin = scene_centre(scene);
  nlohmann::json extras = scene_extras(scene, "light sets", origin);
  extras["faces"]["lit_area"] = std::move(lit);
  std::vector<std::size_t> all(scene.lights.size());
  for (std::size_t l = 0; l < all.size(); ++l) all[l] = l;
  extras["lights"] = light_ids(scene, all);
  out.bytes = output::detail::gltf_file(materials, outline_points(scene, options), origin, extras,
                                        form, options);
  return out;
}

std::string sun_hours_gltf_export(const ShadowedScene& shadowed, const SunPathHours& path,
                                  const HourBands& bands, GltfForm form,
                                  const GltfOptions& options) {
  const Scene& scene = shadowed.scene();
  require_regions(path, scene.file, "an export by hour bands");
  if (path.regions.size() != scene.faces.size()) {
    throw std::invalid_argument("sun_hours_gltf_export: sun-hours regions not shaped [face]");
  }
  std::vector<GltfMaterial> materials;
  for (const HourBand& band : bands.bands) {
    materials.push_back({band.name,
                         band.colour,
                         {{"label", band.label}, {"from", band.from}, {"to", band.to}},
                         {}});
  }
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (const SunHoursRegion& region : path.regions[f]) {
      GltfMaterial& material = materials[bands.band_of(region.hours)];
      if (!material.mesh.add_piece(scene.faces[f], f, region.polygons, lit_area(region.polygons),
                                   region.hours)) {
        // Not the input's fault: valid regions always triangulate.
        throw GenerationError("", scene.faces[f].id, "",
                              "a sun-hours region of " + shortest(region.hours) +
                                  " h could not be split into triangles");
      }
    }
  }

  const glm::dvec3 origin = scene_centre(scene);
  nlohmann::json extras = scene_extras(scene, "sun hours", origin);
  extras["sun_path"] = {{"id", path.id},
                        {"step_min", path.step_min},
                        {"instants", path.instants.size()},
                        {"most_hours", bands.most_hours},
                        {"caption", bands.caption()}};
  return output::detail::gltf_file(materials, outline_points(scene, options), origin, extras, form,
                                   options);
}

}  // namespace shadowgen
