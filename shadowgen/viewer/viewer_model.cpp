#include "shadowgen/viewer/viewer_model.h"

#include <cmath>
#include <filesystem>
#include <glm/common.hpp>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

#include "detail/base64.h"
#include "hsr/area.h"
#include "shadowgen/model/scene_centre.h"
#include "shadowgen/output/gltf_export.h"
#include "shadowgen/output/obj_export.h"

namespace shadowgen {
namespace {

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

// The page's description, less its groups and faces: the origin, the title, the views and
// the north axis.
void describe_scene(nlohmann::json& description, const Scene& scene) {
  description["origin"] = vec(scene_centre(scene));
  description["title"] = std::filesystem::path(scene.file).filename().string();
  nlohmann::json views = nlohmann::json::array();
  for (const ViewSpec& view : scene.views) {
    views.push_back({{"id", view.id},
                     {"eye", vec(view.eye)},
                     {"target", vec(view.target)},
                     {"up", vec(view.up)},
                     {"fov_deg", view.fov_deg}});
  }
  description["views"] = views;
  if (const std::optional<double> north = north_axis_deg(scene)) {
    description["north_axis_deg"] = *north;
  }
}

// What the page asks of the glTF export beyond the file `export` writes.
constexpr GltfOptions kPageModel = {.face_attribute = true, .outlines = true};

double face_area(const Face& face) {
  double area = 0.0;
  for (const hsr::Polygon3& part : face.parts) area += hsr::area(part);
  return area;
}

}  // namespace

ViewerModel viewer_model(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene();
  LightSetGltf gltf = light_set_gltf(shadowed, GltfForm::kBinary, kPageModel);
  // The page's lights: those some light set holds, in the scene's order.
  std::vector<std::size_t> page_light(scene.lights.size(), scene.lights.size());
  std::vector<std::size_t> lights;
  for (const LightSetGltf::Material& material : gltf.materials) {
    for (const std::size_t l : material.lights) page_light[l] = 0;
  }
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    if (page_light[l] == 0) {
      page_light[l] = lights.size();
      lights.push_back(l);
    }
  }

  nlohmann::json description = {{"caption", {"Light sets: the lights reaching each piece"}}};
  // The groups are the file's materials, in its order.
  nlohmann::json groups = nlohmann::json::array();
  for (const LightSetGltf::Material& material : gltf.materials) {
    nlohmann::json in_page = nlohmann::json::array();
    for (const std::size_t l : material.lights) in_page.push_back(page_light[l]);
    groups.push_back({{"name", material.name},
                      {"label", material.lights.empty() ? "shadow (no light)" : material.name},
                      {"colour", vec(light_set_colour(scene, material.lights))},
                      {"lights", in_page}});
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

  const LitAreas lit_areas(shadowed);
  nlohmann::json faces = nlohmann::json::array();
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    nlohmann::json lit = nlohmann::json::array();
    for (const std::size_t l : lights) lit.push_back(lit_areas(f, l));
    faces.push_back({{"id", scene.faces[f].id}, {"area", face_area(scene.faces[f])}, {"lit", lit}});
  }
  description["faces"] = faces;
  describe_scene(description, scene);
  return {std::move(gltf.bytes), description.dump()};
}

ViewerModel viewer_model(const ShadowedScene& shadowed, const SunPathHours& path,
                         const HourBands& bands) {
  const Scene& scene = shadowed.scene();
  require_regions(path, scene.file, "the viewer's sun-hours map");
  if (path.regions.size() != scene.faces.size()) {
    throw std::invalid_argument("the sun path's sun-hours regions are not one list per face");
  }
  // The groups are the file's materials: the bands, in order.
  nlohmann::json description = {{"caption", bands.caption()}};
  nlohmann::json groups = nlohmann::json::array();
  for (const HourBand& band : bands.bands) {
    groups.push_back({{"name", band.name},
                      {"label", band.label},
                      {"colour", vec(band.colour)},
                      {"from", band.from},
                      {"to", band.to}});
  }
  description["groups"] = groups;
  nlohmann::json faces = nlohmann::json::array();
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    double weighted = 0.0;
    for (const SunHoursRegion& region : path.regions[f]) {
      weighted += region.hours * lit_area(region.polygons);
    }
    const double area = face_area(scene.faces[f]);
    faces.push_back(
        {{"id", scene.faces[f].id}, {"area", area}, {"hours", area > 0.0 ? weighted / area : 0.0}});
  }
  description["faces"] = faces;
  describe_scene(description, scene);
  return {sun_hours_gltf_export(shadowed, path, bands, GltfForm::kBinary, kPageModel),
          description.dump()};
}

std::string viewer_model_script(const ViewerModel& model) {
  std::string script = "window.shadowgenModel = {\"meta\": ";
  script += model.description;
  script += ", \"glb\": \"";
  script += viewer::detail::base64(model.glb);
  script += "\"};\n";
  return script;
}

}  // namespace shadowgen
