#include "shadowgen/scene/scene_reader.h"

#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "detail/face_builder.h"
#include "detail/group_entry.h"
#include "detail/json_entities.h"
#include "detail/lamp_depths.h"
#include "detail/mesh_entry.h"
#include "detail/site_entry.h"
#include "detail/sun_light.h"
#include "detail/warning_summary.h"
#include "detail/weather_entry.h"
#include "shadowgen/json/document.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen {
namespace {

constexpr std::string_view kFormat = "shadowgen-scene/1";

// Calls read(entry) for every entry of the array at `key`, when the scene has the key.
template <class Read>
void for_each_entry(JsonObject& top, const char* key, Read&& read) {
  if (const std::optional<JsonValue> value = top.find(key)) {
    const JsonArray list = value->array();
    for (std::size_t i = 0; i < list.size(); ++i) read(list.at(i));
  }
}

class SceneParser {
 public:
  SceneParser(const std::filesystem::path& path, const ReadOptions& options)
      : path_(path), file_(path.string()), options_(options) {}

  ReadResult run(const std::string& text) {
    result_.scene.file = file_;
    const JsonDocument document(text, {file_, options_.strict, &result_.warnings});
    const JsonValue root = document.root();
    if (!root.is_object()) {
      root.fail("a scene is a JSON object; found " + root.describe());
    }
    JsonObject top = root.object();
    check_format(top);
    check_has_faces(top);
    result_.scene.files.push_back(file_);
    detail::WarningSummary polygon_warnings(file_, "polygons");
    for_each_entry(top, "polygons",
                   [&](const JsonValue& entry) { read_polygon_entry(entry, polygon_warnings); });
    polygon_warnings.append_to(result_.warnings, options_.verbose);
    for_each_entry(top, "meshes", [&](const JsonValue& entry) {
      detail::MeshEntryRead read = detail::read_mesh_entry(entry, path_, options_, face_ids_,
                                                           result_.scene.faces, result_.warnings);
      if (!read.site.empty()) model_sites_.push_back({std::move(read.site), read.file});
      result_.scene.files.push_back(std::move(read.file));
    });
    read_site_and_weather(top);
    for_each_entry(top, "lights", [&](const JsonValue& entry) { read_light_entry(entry); });
    for_each_entry(top, "views", [&](const JsonValue& entry) {
      result_.scene.views.push_back(detail::read_view(entry, view_ids_, detail::Source::kScene));
    });
    if (const std::optional<JsonValue> groups = top.find("groups")) {
      result_.scene.groups = detail::read_groups(*groups, result_.scene.faces);
    }
    top.finish();
    detail::check_lamp_depths(result_.scene);
    return std::move(result_);
  }

 private:
  static void check_format(JsonObject& top) {
    const JsonValue value = top.get("format");
    const std::string format = value.string();
    if (format != kFormat) {
      value.fail("unsupported format '" + format + "'; this reader reads '" + std::string(kFormat) +
                 "'");
    }
  }

  // A scene has faces from "polygons", "meshes" or both (either may be empty); a
  // misspelt key must not pass for an empty scene, so it is named here, as an error.
  static void check_has_faces(JsonObject& top) {
    const bool has_polygons = top.has("polygons");
    if (top.has("meshes") || has_polygons) return;
    for (const char* key : {"lights", "views", "site", "weather", "groups"}) (void)top.has(key);
    std::string problem =
        "a scene needs \"polygons\" or \"meshes\" (either may be empty); neither is present";
    for (const std::string& key : top.unknown_keys()) {
      problem += "; " + top.unknown_key_problem(key);
    }
    top.value().fail(problem);
  }

  // Before the lights: a `sun` light needs the site, whose keys the scene, its model
  // files and its weather file give, in that order (detail/site_entry.h).
  void read_site_and_weather(JsonObject& top) {
    Scene& scene = result_.scene;
    std::vector<detail::SiteGiver> givers;
    const std::optional<JsonValue> site = top.find("site");
    if (site) givers.push_back({detail::read_site_keys(*site), file_});
    givers.insert(givers.end(), model_sites_.begin(), model_sites_.end());
    if (const std::optional<JsonValue> weather = top.find("weather")) {
      scene.weather = detail::read_weather(*weather, path_);
      scene.files.push_back(scene.weather->file);
      givers.push_back(detail::site_giver_of(*scene.weather));
    }
    detail::MergedSite merged = detail::merge_site(givers);
    if (site && !merged.site) site->fail(merged.incomplete);
    scene.site = merged.site;
    site_incomplete_ = merged.incomplete;
    if (site && scene.weather) detail::warn_if_site_differs(*scene.site, *site, *scene.weather);
  }

  // A `sun` entry becomes the directional lights of its instants, where it stands.
  void read_light_entry(const JsonValue& value) {
    std::vector<Light>& lights = result_.scene.lights;
    if (!detail::is_sun_light(value)) {
      lights.push_back(detail::read_light(value, light_ids_, detail::Source::kScene));
      return;
    }
    detail::SunEntryRead sun =
        detail::read_sun_light(value, light_ids_, result_.scene.site, site_incomplete_);
    lights.insert(lights.end(), std::make_move_iterator(sun.lights.begin()),
                  std::make_move_iterator(sun.lights.end()));
    if (sun.path) result_.scene.sun_paths.push_back(std::move(*sun.path));
  }

  // Polygon ids and mesh ids share one namespace (a polygon id never contains '/', and a
  // mesh face id always does, so face ids are then unique too); lights and views each
  // have their own. The face's warnings go to `summary`.
  void read_polygon_entry(const JsonValue& value, detail::WarningSummary& summary) {
    JsonObject entry = value.object();
    const std::string id = detail::read_id(entry);
    if (id.find('/') != std::string::npos) {
      throw InputError(file_, id, "a polygon id must not contain '/' (mesh face ids use it)");
    }
    face_ids_.claim(id, "polygon '" + id + "'", entry.get("id"));
    entry.for_face(id);
    hsr::Polygon3 polygon = detail::read_polygon(entry);
    entry.finish();
    std::vector<std::string> face_warnings;
    result_.scene.faces.push_back(detail::build_face(std::move(polygon),
                                                     {id, file_, detail::FaceKind::kPolygon},
                                                     options_.strict, face_warnings));
    for (std::string& line : face_warnings) summary.add(id, std::move(line));
  }

  const std::filesystem::path path_;
  const std::string file_;
  const ReadOptions options_;
  ReadResult result_;
  detail::IdRegistry face_ids_;
  detail::IdRegistry light_ids_;
  detail::IdRegistry view_ids_;
  std::vector<detail::SiteGiver> model_sites_;  // what model files tell of the site
  std::string site_incomplete_;  // why the keys given make no site, when some are given
};

}  // namespace

ReadResult read_scene(const std::filesystem::path& path, const ReadOptions& options) {
  return parse_scene(read_text_file(path, "scene file"), path, options);
}

ReadResult parse_scene(const std::string& json_text, const std::filesystem::path& path,
                       const ReadOptions& options) {
  return SceneParser(path, options).run(json_text);
}

}  // namespace shadowgen
