#include "shadowgen/scene/database_reader.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "detail/database_checks.h"
#include "detail/database_header.h"
#include "detail/database_polygons.h"
#include "detail/database_sun_hours.h"
#include "detail/face_builder.h"
#include "detail/group_entry.h"
#include "detail/indexed_polygons.h"
#include "detail/json_entities.h"
#include "detail/lit_checks.h"
#include "hsr/area.h"
#include "shadowgen/compressed/decompressed_input.h"
#include "shadowgen/database/database_format.h"
#include "shadowgen/json/document.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen {
namespace {

namespace key = database::key;

class DatabaseParser {
 public:
  DatabaseParser(const std::filesystem::path& path, const ReadOptions& options,
                 std::vector<std::string>& warnings)
      : path_(path), file_(path.string()), options_(options), warnings_(warnings) {}

  // Faces come last in a database as written (shadowgen/output/database.h), and make
  // nearly all of it: each is read as soon as the parser has it and its tree dropped, so
  // reading holds the scene and one face's tree, never the whole document's tree
  // (several times the text). The members before "faces" (the header) are read at its
  // first element. JSON objects are unordered, though: where a member of the header
  // comes after "faces" (a file arranged by hand), the faces streamed were read too
  // early (as exact where the method comes later, whole where the shard does), so what
  // reading them threw waits for the end of this pass, and they are read again in a
  // second pass, with the header this pass found after them (read_faces_after). Where
  // the format, the lights or the views come after "faces", no face is read in this
  // pass at all. Either way reading holds one face's tree at a time; the cost is a
  // second parse. Read from a file, the text itself is never held whole either.
  // From `text`, or where it is null from the file, read as it is parsed.
  ShadowedScene run(const std::string* text) {
    ShadowedScene shadowed;
    shadowed.edit_scene([this](Scene& scene) { scene.file = file_; });
    std::optional<JsonObject> top;
    bool skipping = false;          // a member the header needs comes after the faces
    std::exception_ptr too_early;   // what reading the header or a face threw in this pass
    std::vector<bool> header_then;  // the header's members before the first face
    const std::size_t warnings_before = warnings_.size();
    const auto take = [&](const JsonValue& root, const JsonValue& face) {
      if (!top && !skipping) {
        header_then = header_present(root);
        skipping = !header_then[kFormat] || !header_then[kLights] || !header_then[kViews];
        if (!skipping) {
          top.emplace(root.object());
          guarded(too_early, [&] { read_header(*top, shadowed); });
        }
      }
      if (!skipping && !too_early) guarded(too_early, [&] { read_face(face, shadowed); });
      return true;  // dropped: read, or left for the second pass
    };
    std::optional<compressed::DecompressedInput> in;
    std::optional<JsonDocument> document;
    parse(text, take, in, document);
    const JsonValue root = document->root();
    if (!root.is_object()) {
      root.fail("a shadowed database is a JSON object; found " + root.describe());
    }
    if (skipping || (top && header_present(root) != header_then)) {
      shadowed = {};
      warnings_.resize(warnings_before);
      return DatabaseParser(path_, options_, warnings_).read_faces_after(root, text);
    }
    if (too_early) std::rethrow_exception(too_early);
    if (!top) {  // no face
      top.emplace(root.object());
      read_header(*top, shadowed);
    }
    return finished(*top, std::move(shadowed));
  }

 private:
  // Runs `read`, keeping what it throws as bad input in `error` instead.
  template <class Read>
  static void guarded(std::exception_ptr& error, const Read& read) {
    try {
      read();
    } catch (const InputError&) {
      error = std::current_exception();
    }
  }

  // Parses the database, from `text` or where it is null from the file (opened in `in`),
  // into `document`, handing each face to `take` as it comes.
  void parse(const std::string* text, const JsonDocument::ElementTaker& take,
             std::optional<compressed::DecompressedInput>& in,
             std::optional<JsonDocument>& document) const {
    const JsonSource source{file_, options_.strict, &warnings_};
    if (text != nullptr) {
      document.emplace(*text, source, key::kFaces, take);
    } else {
      in.emplace(open_input_file(path_), file_);
      document.emplace(*in, source, key::kFaces, take);
    }
  }

  // The second pass: the header from `first`, the root of a first pass that read every
  // member but the faces, then the faces as this pass parses them.
  ShadowedScene read_faces_after(const JsonValue& first, const std::string* text) {
    ShadowedScene shadowed;
    JsonObject top = first.object();
    read_header(top, shadowed);
    const auto take = [&](const JsonValue&, const JsonValue& face) {
      read_face(face, shadowed);
      return true;
    };
    std::optional<compressed::DecompressedInput> in;
    std::optional<JsonDocument> document;
    parse(text, take, in, document);
    return finished(top, std::move(shadowed));
  }

  // The checks once every member is read: no unknown key at the top, the lit polygons and
  // the sun hours (checked with every face read); the groups, whose patterns must match
  // faces, wherever they stand.
  ShadowedScene finished(JsonObject& top, ShadowedScene shadowed) const {
    (void)top.get(key::kFaces).array();
    if (const std::optional<JsonValue> groups = top.find(key::kGroups)) {
      std::vector<FaceGroupSpec> read = scene::detail::read_groups(*groups, shadowed.scene().faces);
      shadowed.edit_scene([&read](Scene& scene) { scene.groups = std::move(read); });
    }
    top.finish();
    scene::detail::check_lit_lists(shadowed, lists_of_face_, lists_);
    scene::detail::check_sun_hours_sums(shadowed, path_values_);
    return shadowed;
  }

  // Everything but the faces (detail/database_header.h); per sun path, where each face's
  // sums over it stand, for the checks.
  void read_header(JsonObject& top, ShadowedScene& shadowed) {
    header_ = scene::detail::read_database_header(top, shadowed);
    path_values_.resize(shadowed.sun_paths.size());
  }

  // The members read before the faces, in this order: which of them the root has.
  static constexpr const char* kHeader[] = {key::kFormat, key::kShard, key::kMethod,
                                            key::kLights, key::kViews, key::kSunPaths,
                                            key::kSite};
  static constexpr std::size_t kFormat = 0, kLights = 3, kViews = 4;  // required ones in it
  static std::vector<bool> header_present(const JsonValue& root) {
    std::vector<bool> present;
    if (!root.is_object()) return present;
    JsonObject object = root.object();  // a look only: this one is never finished
    for (const char* key : kHeader) present.push_back(object.has(key));
    return present;
  }

  // A face's "origin" (shadowgen/output/detail/origin_json.h): every member a string,
  // "format" not empty.
  static FaceOrigin read_origin(const JsonValue& value) {
    JsonObject object = value.object();
    FaceOrigin origin;
    const JsonValue format = object.get(key::kFormat);
    origin.format = format.string();
    if (origin.format.empty())
      format.fail("must name the format the face comes from, not be empty");
    origin.object = object.get("object").string();
    origin.group = object.get("group").string();
    origin.semantic = object.get("semantic").string();
    object.finish();
    return origin;
  }

  void read_face(const JsonValue& value, ShadowedScene& shadowed) {
    JsonObject entry = value.object();
    Face face;
    face.id = scene::detail::read_id(entry);
    face_ids_.claim(face.id, "another face", entry.get("id"));
    entry.for_face(face.id);
    face.source_file = entry.get(key::kSourceFile).string();
    if (const std::optional<JsonValue> origin = entry.find(key::kOrigin))
      face.origin = read_origin(*origin);
    if (const std::optional<JsonValue> rounding = entry.find(key::kVertexRounding)) {
      face.vertex_rounding = rounding->number();
      if (!(face.vertex_rounding >= 0.0)) rounding->fail("a vertex rounding cannot be negative");
    }
    const JsonValue parts_value = entry.get(key::kParts);
    const JsonArray parts = parts_value.array();
    if (parts.empty()) parts_value.fail("a face needs at least one polygon");
    for (std::size_t k = 0; k < parts.size(); ++k) {
      JsonObject part = parts.at(k).object();
      hsr::Polygon3 polygon = scene::detail::read_polygon(part);
      part.finish();
      face.parts.push_back(scene::detail::checked_database_part(
          std::move(polygon), part.value(),
          {face.id, file_, scene::detail::FaceKind::kPolygon, face.vertex_rounding}, warnings_));
    }
    if (!std::isfinite(hsr::area(face.parts))) {
      parts_value.fail("the face's area is not a finite number (coordinates too large)");
    }
    if (header_.layout == database::Layout::kIndexed)
      vertices_ = scene::detail::read_face_vertices(entry);
    lists_of_face_.push_back(lists_.size());
    if (const std::optional<Estimate>& estimate = shadowed.estimate()) {
      std::vector<std::optional<double>> areas = read_estimated(entry, face, *estimate, shadowed);
      scene::detail::read_face_sun_hours(entry, face, shadowed, {header_.layout, vertices_},
                                         path_values_);
      entry.finish();
      shadowed.add_face(std::move(face), areas);
      return;
    }
    std::vector<std::pair<std::size_t, LitTable::Polygons>> lit;
    for (const auto& [light_id, list] : entry.get(key::kLit).object().entries()) {
      const auto light = header_.light_index.find(light_id);
      if (light == header_.light_index.end()) list.fail("no light has this id");
      if (!shadowed.lit().kept(light->second)) {
        list.fail("the light is an instant of sun path '" +
                  one_line(path_of(shadowed, light->second)) +
                  "', whose instant polygons are \"dropped\": only its lit areas are kept");
      }
      // A shard keeps no instant's polygons (read_sun_paths), so a light it keeps is no
      // instant of a path: shard 1 alone lights those, and merge takes them from it.
      if (shadowed.shard && shadowed.shard->index != 0 && !list.array().empty()) {
        list.fail("is shard " + std::to_string(shadowed.shard->index + 1) + " of " +
                  std::to_string(shadowed.shard->count) +
                  ", which holds no lit polygons: the lights that are no instant of a sun "
                  "path are lit in shard 1 alone");
      }
      lit.emplace_back(light->second,
                       scene::detail::read_database_lit(list, face, {header_.layout, vertices_}));
      lists_.push_back({light->second, list.place()});
    }
    scene::detail::read_face_sun_hours(entry, face, shadowed, {header_.layout, vertices_},
                                       path_values_);
    entry.finish();
    const std::size_t f = shadowed.scene().faces.size();
    shadowed.add_face(std::move(face));
    for (auto& [light, polygons] : lit) shadowed.lit_at(f, light) = std::move(polygons);
  }

  // A sampled method's "lit_area": {"light id": area, ...}, one for every light that is no
  // instant of a sun path (an instant's area is in the face's "sun_hours"), each from 0 to
  // the face's area.
  std::vector<std::optional<double>> read_estimated(JsonObject& entry, const Face& face,
                                                    const Estimate& estimate,
                                                    const ShadowedScene& shadowed) const {
    if (const std::optional<JsonValue> lit = entry.find(key::kLit)) {
      lit->fail("a database made by the " + std::string(method_name(estimate.method.kind)) +
                " method holds lit areas (\"lit_area\"), not lit polygons");
    }
    const JsonValue areas_value = entry.get(key::kLitArea);
    std::vector<std::optional<double>> areas(shadowed.scene().lights.size());
    const double face_area = hsr::area(face.parts);
    const double tolerance = scene::detail::LitChecker(face).area_tolerance({});
    for (const auto& [light_id, value] : areas_value.object().entries()) {
      const auto light = header_.light_index.find(light_id);
      if (light == header_.light_index.end()) value.fail("no light has this id");
      const std::size_t l = light->second;
      if (header_.instant[l]) {
        value.fail("the light is an instant of sun path '" + one_line(path_of(shadowed, l)) +
                   "', whose lit areas are in the face's \"sun_hours\"");
      }
      const double a = value.number();
      if (a < 0.0 || a > face_area + tolerance) {
        value.fail("a lit area of " + shortest(a) + " is not between 0 and the face's area of " +
                   shortest(face_area));
      }
      areas[l] = a;
    }
    for (std::size_t l = 0; l < areas.size(); ++l) {
      if (!areas[l] && !header_.instant[l]) {
        areas_value.fail("no lit area for light '" + one_line(shadowed.scene().lights[l].id) + "'");
      }
    }
    return areas;
  }

  static const std::string& path_of(const ShadowedScene& shadowed, std::size_t light) {
    for (const SunPathHours& path : shadowed.sun_paths) {
      if (std::find(path.instants.begin(), path.instants.end(), light) != path.instants.end()) {
        return path.id;
      }
    }
    throw std::logic_error("database reader: light " + std::to_string(light) + " is in no path");
  }

  const std::filesystem::path path_;
  const std::string file_;
  const ReadOptions options_;
  std::vector<std::string>& warnings_;
  scene::detail::IdRegistry face_ids_;
  scene::detail::DatabaseHeader header_;
  // Each face's lists of lit polygons, checked once all are read: where each face's lists
  // start in lists_, and per list its light and where it stands in the file.
  std::vector<std::size_t> lists_of_face_;
  std::vector<scene::detail::LitList> lists_;
  std::vector<std::vector<JsonPlace>> path_values_;  // [path][face]: faces[f].sun_hours.<path>
  std::vector<glm::dvec3> vertices_;  // the face being read: its shared vertices (indexed)
};

}  // namespace

ShadowedScene parse_database(const std::string& json_text, const std::filesystem::path& path,
                             const ReadOptions& options, std::vector<std::string>& warnings) {
  return DatabaseParser(path, options, warnings).run(&json_text);
}

ShadowedScene read_database(const std::filesystem::path& path, const ReadOptions& options,
                            std::vector<std::string>& warnings) {
  if (path == "-") {
    return parse_database(compressed::decompressed_text(read_text_file(path), path.string()), path,
                          options, warnings);
  }
  return DatabaseParser(path, options, warnings).run(nullptr);
}

ShadowedScene parse_database(const std::string& json_text, const std::filesystem::path& path) {
  std::vector<std::string> warnings;
  return parse_database(json_text, path, {}, warnings);
}

ShadowedScene read_database(const std::filesystem::path& path) {
  std::vector<std::string> warnings;
  return read_database(path, {}, warnings);
}

}  // namespace shadowgen
