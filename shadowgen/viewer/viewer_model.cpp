#include "shadowgen/viewer/viewer_model.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/common.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "detail/base64.h"
#include "detail/glb_file.h"
#include "hsr/area.h"
#include "shadowgen/model/scene_centre.h"
#include "shadowgen/output/gltf_space.h"
#include "shadowgen/output/obj_export.h"
#include "shadowgen/sampled/part_triangles.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/shadows/light_regions.h"

namespace shadowgen {
namespace {

using LightSet = std::vector<std::size_t>;

// The scene's axes (+z up) to glTF's (+y up).

nlohmann::json vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// The angle from true north to the scene's +y, clockwise seen from above: the site's (a
// database keeps its scene's), or else, for a database written before databases kept it,
// what a sun instant's azimuth and direction say: the way to the sun is at its azimuth clockwise
// from north, and at atan2(x, y) clockwise from +y. None where neither is known, or the only suns
// stand overhead.
std::optional<double> north_axis_deg(const Scene& scene) {
  if (scene.site) return scene.site->north_axis_deg;
  for (const Light& light : scene.lights) {
    if (!light.sun) continue;
    const glm::dvec3 to_sun = -light.direction;
    if (to_sun.x == 0.0 && to_sun.y == 0.0) continue;
    const double from_y = std::atan2(to_sun.x, to_sun.y) * 180.0 / std::numbers::pi;
    double north = light.sun->azimuth_deg - from_y;
    north -= 360.0 * std::round(north / 360.0);  // in [-180, 180]
    return north;
  }
  return std::nullopt;
}

// The model in the making: one triangle mesh per group, the outlines, the description.
class ModelBuilder {
 public:
  ModelBuilder(const ShadowedScene& shadowed, std::size_t groups)
      : scene_(shadowed.scene), origin_(scene_centre(scene_)), meshes_(groups) {
    for (const Face& face : scene_.faces) {
      for (const hsr::Polygon3& part : face.parts) {
        add_loop(part.outer);
        for (const hsr::Loop3& hole : part.holes) add_loop(hole);
      }
    }
  }

  // The triangles of `polygons` of face `face` into group `group`.
  void add_pieces(std::size_t group, std::size_t face, std::span<const LitPolygon> polygons) {
    detail::GlbMesh& mesh = meshes_[group];
    for (const LitPolygon& piece : polygons) {
      sampled::PartTriangles triangles;
      try {
        triangles = sampled::part_triangles(piece.polygon);
      } catch (const std::runtime_error&) {
        // Not the input's fault: valid regions always triangulate.
        throw GenerationError("", scene_.faces[face].id, "",
                              "a region could not be split into triangles for the viewer");
      }
      // A vertex is shared by the piece's triangles (the ear clipping's corners are the
      // piece's own vertices, so equal points are one vertex).
      std::map<std::tuple<double, double, double>, std::uint32_t> index;
      for (const sampled::Triangle3& t : triangles.triangles) {
        for (const glm::dvec3& p : {t.a, t.b, t.c}) {
          const auto [at, added] =
              index.try_emplace({p.x, p.y, p.z}, static_cast<std::uint32_t>(mesh.faces.size()));
          if (added) {
            add_position(mesh.positions, p);
            mesh.faces.push_back(static_cast<float>(face));
          }
          mesh.indices.push_back(at->second);
        }
      }
    }
  }

  // The model whose groups are `groups` (the description's entries, with their colour).
  ViewerModel finish(nlohmann::json description, const std::vector<glm::dvec3>& colours) {
    std::vector<detail::GlbMesh> meshes;
    for (std::size_t g = 0; g < meshes_.size(); ++g) {
      if (meshes_[g].positions.empty()) continue;
      meshes_[g].name = description["groups"][g]["name"];
      meshes_[g].colour = colours[g];
      meshes_[g].node_extras = {{"group", g}};
      meshes.push_back(std::move(meshes_[g]));
    }
    if (!outline_.positions.empty()) {
      outline_.name = "outlines";
      outline_.lines = true;
      outline_.colour = glm::dvec3(0.2);
      outline_.node_extras = {{"outline", true}};
      meshes.push_back(std::move(outline_));
    }
    description["origin"] = vec(origin_);
    description["title"] = std::filesystem::path(scene_.file).filename().string();
    nlohmann::json views = nlohmann::json::array();
    for (const ViewSpec& view : scene_.views) {
      views.push_back({{"id", view.id},
                       {"eye", vec(view.eye)},
                       {"target", vec(view.target)},
                       {"up", vec(view.up)},
                       {"fov_deg", view.fov_deg}});
    }
    description["views"] = views;
    if (const std::optional<double> north = north_axis_deg(scene_)) {
      description["north_axis_deg"] = *north;
    }
    ViewerModel model;
    model.glb = detail::glb_file(meshes, gltf_axes(origin_));
    model.description = description.dump();
    return model;
  }

 private:
  void add_position(std::vector<float>& out, const glm::dvec3& p) const {
    const glm::dvec3 q = gltf_axes(p - origin_);
    out.push_back(static_cast<float>(q.x));
    out.push_back(static_cast<float>(q.y));
    out.push_back(static_cast<float>(q.z));
  }

  void add_loop(const hsr::Loop3& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      add_position(outline_.positions, loop[i]);
      add_position(outline_.positions, loop[(i + 1) % loop.size()]);
    }
  }

  const Scene& scene_;
  glm::dvec3 origin_;
  std::vector<detail::GlbMesh> meshes_;
  detail::GlbMesh outline_;
};

double face_area(const Face& face) {
  double area = 0.0;
  for (const hsr::Polygon3& part : face.parts) area += hsr::area(part);
  return area;
}

}  // namespace

ViewerModel viewer_model(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene;
  check_lit_shape(shadowed, "viewer_model");
  std::vector<std::vector<LightRegion>> regions(scene.faces.size());
  std::map<LightSet, std::size_t, LightSetLess> sets;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    regions[f] = light_regions(shadowed, f);
    for (const LightRegion& r : regions[f]) sets.emplace(r.lights, 0);
  }
  // The page's lights: those some light set holds, in the scene's order.
  std::vector<std::size_t> page_light(scene.lights.size(), scene.lights.size());
  std::vector<std::size_t> lights;
  for (const auto& [set, unused] : sets) {
    for (const std::size_t l : set) page_light[l] = 0;
  }
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    if (page_light[l] == 0) {
      page_light[l] = lights.size();
      lights.push_back(l);
    }
  }

  nlohmann::json description = {{"caption", {"Light sets: the lights reaching each piece"}}};
  nlohmann::json groups = nlohmann::json::array();
  std::vector<glm::dvec3> colours;
  for (auto& [set, index] : sets) {
    index = groups.size();
    const glm::dvec3 colour = light_set_colour(scene, set);
    nlohmann::json in_page = nlohmann::json::array();
    for (const std::size_t l : set) in_page.push_back(page_light[l]);
    const std::string name = light_set_name(scene, set);
    groups.push_back({{"name", name},
                      {"label", set.empty() ? "shadow (no light)" : name},
                      {"colour", vec(colour)},
                      {"lights", in_page}});
    colours.push_back(colour);
  }
  description["groups"] = groups;
  nlohmann::json page_lights = nlohmann::json::array();
  glm::dvec3 total(0.0);
  for (const Light& light : scene.lights) total += glm::max(light.intensity, glm::dvec3(0.0));
  for (const std::size_t l : lights) {
    page_lights.push_back(
        {{"id", scene.lights[l].id}, {"intensity", vec(scene.lights[l].intensity)}});
  }
  description["lights"] = page_lights;
  description["total_intensity"] = vec(total);

  ModelBuilder builder(shadowed, groups.size());
  const LitAreas lit_areas(shadowed);
  nlohmann::json faces = nlohmann::json::array();
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (const LightRegion& r : regions[f]) builder.add_pieces(sets.at(r.lights), f, r.polygons);
    nlohmann::json lit = nlohmann::json::array();
    for (const std::size_t l : lights) lit.push_back(lit_areas(f, l));
    faces.push_back({{"id", scene.faces[f].id}, {"area", face_area(scene.faces[f])}, {"lit", lit}});
  }
  description["faces"] = faces;
  return builder.finish(std::move(description), colours);
}

ViewerModel viewer_model(const ShadowedScene& shadowed, const SunPathHours& path,
                         const HourBands& bands) {
  const Scene& scene = shadowed.scene;
  require_regions(path, scene.file, "the viewer's sun-hours map");
  if (path.regions.size() != scene.faces.size()) {
    throw std::invalid_argument("the sun path's sun-hours regions are not one list per face");
  }
  nlohmann::json description = {{"caption", bands.caption()}};
  nlohmann::json groups = nlohmann::json::array();
  std::vector<glm::dvec3> colours;
  for (const HourBand& band : bands.bands) {
    groups.push_back({{"name", band.name},
                      {"label", band.label},
                      {"colour", vec(band.colour)},
                      {"from", band.from},
                      {"to", band.to}});
    colours.push_back(band.colour);
  }
  description["groups"] = groups;
  ModelBuilder builder(shadowed, groups.size());
  nlohmann::json faces = nlohmann::json::array();
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    double weighted = 0.0;
    for (const SunHoursRegion& region : path.regions[f]) {
      builder.add_pieces(bands.band_of(region.hours), f, region.polygons);
      weighted += region.hours * lit_area(region.polygons);
    }
    const double area = face_area(scene.faces[f]);
    faces.push_back(
        {{"id", scene.faces[f].id}, {"area", area}, {"hours", area > 0.0 ? weighted / area : 0.0}});
  }
  description["faces"] = faces;
  return builder.finish(std::move(description), colours);
}

std::string viewer_model_script(const ViewerModel& model) {
  std::string script = "window.shadowgenModel = {\"meta\": ";
  script += model.description;
  script += ", \"glb\": \"";
  script += detail::base64(model.glb);
  script += "\"};\n";
  return script;
}

}  // namespace shadowgen
