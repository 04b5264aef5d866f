#include "shadowgen/scene/scene_reader.h"

#include <exception>
#include <iterator>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "detail/distinct_ids.h"
#include "detail/group_entry.h"
#include "detail/json_entities.h"
#include "detail/lamp_depths.h"
#include "detail/mesh_entry.h"
#include "detail/polygon_entries.h"
#include "detail/site_entry.h"
#include "detail/sun_light.h"
#include "detail/warning_summary.h"
#include "detail/weather_entry.h"
#include "shadowgen/compressed/decompressed_input.h"
#include "shadowgen/json/array_member_cut.h"
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

  // `cut`: the text cut at its polygons (json/array_member_cut.h), whose elements are then
  // read in parallel; null to read the document whole, in order.
  ReadResult run(const std::string& text, const ArrayMemberCut* cut) {
    result_.scene.file = file_;
    const JsonDocument document(cut != nullptr ? cut->rest : text,
                                {file_, options_.strict, &result_.warnings});
    const JsonValue root = document.root();
    if (!root.is_object()) {
      root.fail("a scene is a JSON object; found " + root.describe());
    }
    JsonObject top = root.object();
    check_format(top);
    check_has_faces(top);
    result_.scene.files.push_back(file_);
    scene::detail::WarningSummary polygon_warnings(file_, "polygons");
    if (cut != nullptr) {
      read_polygon_texts(cut->elements, polygon_warnings, top.has("meshes"));
    } else {
      for_each_entry(top, "polygons",
                     [&](const JsonValue& entry) { read_polygon_entry(entry, polygon_warnings); });
    }
    polygon_warnings.append_to(result_.warnings, options_.verbose);
    for_each_entry(top, "meshes", [&](const JsonValue& entry) {
      scene::detail::MeshEntryRead read = scene::detail::read_mesh_entry(
          entry, path_, options_, face_ids_, result_.scene.faces, result_.warnings);
      if (!read.site.empty()) model_sites_.push_back({std::move(read.site), read.file});
      result_.scene.files.push_back(std::move(read.file));
    });
    read_site_and_weather(top);
    for_each_entry(top, "lights", [&](const JsonValue& entry) { read_light_entry(entry); });
    for_each_entry(top, "views", [&](const JsonValue& entry) {
      result_.scene.views.push_back(
          scene::detail::read_view(entry, view_ids_, scene::detail::Source::kScene));
    });
    if (const std::optional<JsonValue> groups = top.find("groups")) {
      result_.scene.groups = scene::detail::read_groups(*groups, result_.scene.faces);
    }
    top.finish();
    scene::detail::check_lamp_depths(result_.scene);
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
    std::vector<scene::detail::SiteGiver> givers;
    const std::optional<JsonValue> site = top.find("site");
    if (site) givers.push_back({scene::detail::read_site_keys(*site), file_});
    givers.insert(givers.end(), model_sites_.begin(), model_sites_.end());
    if (const std::optional<JsonValue> weather = top.find("weather")) {
      scene.weather = scene::detail::read_weather(*weather, path_);
      scene.files.push_back(scene.weather->file);
      givers.push_back(scene::detail::site_giver_of(*scene.weather));
    }
    scene::detail::MergedSite merged = scene::detail::merge_site(givers);
    if (site && !merged.site) site->fail(merged.incomplete);
    scene.site = merged.site;
    site_incomplete_ = merged.incomplete;
    if (site && scene.weather)
      scene::detail::warn_if_site_differs(*scene.site, *site, *scene.weather);
  }

  // A `sun` entry becomes the directional lights of its instants, where it stands.
  void read_light_entry(const JsonValue& value) {
    std::vector<Light>& lights = result_.scene.lights;
    if (!scene::detail::is_sun_light(value)) {
      lights.push_back(scene::detail::read_light(value, light_ids_, scene::detail::Source::kScene));
      return;
    }
    scene::detail::SunEntryRead sun =
        scene::detail::read_sun_light(value, light_ids_, result_.scene.site, site_incomplete_);
    lights.insert(lights.end(), std::make_move_iterator(sun.lights.begin()),
                  std::make_move_iterator(sun.lights.end()));
    if (sun.path) result_.scene.sun_paths.push_back(std::move(*sun.path));
  }

  // Polygon ids and mesh ids share one namespace (a polygon id never contains '/', and a
  // mesh face id always does, so face ids are then unique too); lights and views each
  // have their own. The face's warnings go to `summary`.
  void read_polygon_entry(const JsonValue& value, scene::detail::WarningSummary& summary) {
    JsonObject entry = value.object();
    const std::string id = scene::detail::read_polygon_id(entry, file_);
    face_ids_.claim(id, polygon_owner(id), entry.get("id"));
    std::vector<std::string> face_warnings;
    result_.scene.faces.push_back(
        scene::detail::read_polygon_face(entry, id, file_, options_.strict, face_warnings));
    for (std::string& line : face_warnings) summary.add(id, std::move(line));
  }

  // The same for every polygon from its own text, in parallel; then their ids checked. A
  // clash throws, without the place: the caller reads the document again in order, which
  // names it. Only where meshes follow, whose ids share the polygons' namespace, are the
  // polygons' ids claimed one by one; else they are checked distinct in parallel.
  void read_polygon_texts(std::span<const std::string_view> texts,
                          scene::detail::WarningSummary& summary, bool meshes_follow) {
    scene::detail::PolygonsRead read =
        scene::detail::read_polygon_texts(texts, file_, options_.strict);
    std::vector<Face>& faces = result_.scene.faces;
    if (meshes_follow) {
      face_ids_.reserve_more(read.faces.size());
      for (const Face& face : read.faces) {
        if (!face_ids_.try_claim(face.id, polygon_owner(face.id))) {
          throw InputError(file_, face.id, "duplicate id");
        }
      }
    } else if (!scene::detail::ids_distinct(read.faces)) {
      throw InputError(file_, "", "duplicate id");
    }
    for (std::size_t i = 0; i < read.faces.size(); ++i) {
      for (std::string& line : read.face_warnings[i])
        summary.add(read.faces[i].id, std::move(line));
    }
    std::move(read.warnings.begin(), read.warnings.end(), std::back_inserter(result_.warnings));
    if (faces.empty()) {
      faces = std::move(read.faces);
    } else {
      std::move(read.faces.begin(), read.faces.end(), std::back_inserter(faces));
    }
  }

  static std::string polygon_owner(const std::string& id) { return "polygon '" + id + "'"; }

  const std::filesystem::path path_;
  const std::string file_;
  const ReadOptions options_;
  ReadResult result_;
  scene::detail::IdRegistry face_ids_;
  scene::detail::IdRegistry light_ids_;
  scene::detail::IdRegistry view_ids_;
  std::vector<scene::detail::SiteGiver> model_sites_;  // what model files tell of the site
  std::string site_incomplete_;  // why the keys given make no site, when some are given
};

}  // namespace

ReadResult read_scene(const std::filesystem::path& path, const ReadOptions& options) {
  // gzip by its magic bytes, as a database is read: a database given for a scene is named
  // as what it is whatever its compression.
  return parse_scene(
      compressed::decompressed_text(read_text_file(path, "scene file"), path.string()), path,
      options);
}

ReadResult parse_scene(const std::string& json_text, const std::filesystem::path& path,
                       const ReadOptions& options) {
  // The polygons, nearly all of a large scene's text, are parsed and checked in parallel,
  // each from its own text. Where anything fails, the whole document is read again in
  // order: what is reported is then what reading in order meets first, as if the
  // polygons had been read one by one (a syntax error anywhere before any polygon's
  // problem, the first polygon's problem before a later one's).
  if (const std::optional<ArrayMemberCut> cut = cut_array_member(json_text, "polygons")) {
    try {
      return SceneParser(path, options).run(json_text, &*cut);
    } catch (const std::exception&) {
      // read again below
    }
  }
  return SceneParser(path, options).run(json_text, nullptr);
}

}  // namespace shadowgen
