#include "shadowgen/scene/database_reader.h"

#include <cmath>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "detail/coordinate_range.h"
#include "detail/face_builder.h"
#include "detail/json_entities.h"
#include "detail/lit_checks.h"
#include "hsr/collinearity.h"
#include "shadowgen/json/document.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen {
namespace {

class DatabaseParser {
 public:
  DatabaseParser(const std::filesystem::path& path, const ReadOptions& options,
                 std::vector<std::string>& warnings)
      : file_(path.string()), options_(options), warnings_(warnings) {}

  ShadowedScene run(const std::string& text) {
    const JsonDocument document(text, {file_, options_.strict, &warnings_});
    const JsonValue root = document.root();
    if (!root.is_object()) {
      root.fail("a shadowed database is a JSON object; found " + root.describe());
    }
    JsonObject top = root.object();
    const JsonValue format = top.get("format");
    if (format.string() != kShadowedFormat) {
      format.fail("unsupported format '" + format.string() + "'; this reader reads '" +
                  std::string(kShadowedFormat) + "'");
    }
    ShadowedScene shadowed;
    const JsonArray lights = top.get("lights").array();
    detail::IdRegistry light_ids;
    for (std::size_t i = 0; i < lights.size(); ++i) {
      shadowed.scene.lights.push_back(
          detail::read_light(lights.at(i), light_ids, detail::Source::kDatabase));
      light_index_.emplace(shadowed.scene.lights.back().id, i);
    }
    const JsonArray views = top.get("views").array();
    detail::IdRegistry view_ids;
    for (std::size_t i = 0; i < views.size(); ++i) {
      shadowed.scene.views.push_back(
          detail::read_view(views.at(i), view_ids, detail::Source::kDatabase));
    }
    const JsonArray faces = top.get("faces").array();
    shadowed.scene.faces.reserve(faces.size());
    shadowed.lit.reserve(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) read_face(faces.at(i), shadowed);
    top.finish();
    return shadowed;
  }

 private:
  void read_face(const JsonValue& value, ShadowedScene& shadowed) {
    JsonObject entry = value.object();
    Face face;
    face.id = detail::read_id(entry);
    face_ids_.claim(face.id, "another face", entry.get("id"));
    entry.for_face(face.id);
    face.source_file = entry.get("source_file").string();
    const JsonValue parts_value = entry.get("parts");
    const JsonArray parts = parts_value.array();
    if (parts.empty()) parts_value.fail("a face needs at least one polygon");
    for (std::size_t k = 0; k < parts.size(); ++k) {
      JsonObject part = parts.at(k).object();
      hsr::Polygon3 polygon = detail::read_polygon(part);
      part.finish();
      face.parts.push_back(checked_part(std::move(polygon), part.value(), face.id));
    }
    const detail::LitChecker checker(face);
    if (!std::isfinite(checker.face_area())) {
      parts_value.fail("the face's area is not a finite number (coordinates too large)");
    }
    std::vector<std::vector<LitPolygon>> lit(shadowed.scene.lights.size());
    for (const auto& [light_id, list] : entry.get("lit").object().entries()) {
      const auto light = light_index_.find(light_id);
      if (light == light_index_.end()) list.fail("no light has this id");
      lit[light->second] = read_lit(list, face, checker);
    }
    entry.finish();
    shadowed.scene.faces.push_back(std::move(face));
    shadowed.lit.push_back(std::move(lit));
  }

  // A part gets the checks a scene's face gets (strict: a part is planar, it was written
  // from a face already split into planar parts). A part without area is kept as it is,
  // as the scene reader keeps a degenerate face; it warned when it read it.
  hsr::Polygon3 checked_part(hsr::Polygon3 polygon, const JsonValue& at,
                             const std::string& face_id) {
    if (const std::optional<std::string> problem = detail::coordinate_problem(polygon)) {
      at.fail(*problem);
    }
    if (polygon.outer.size() >= 3 &&
        (hsr::distinct_points_up_to_3(polygon.outer) < 3 || hsr::all_collinear(polygon.outer))) {
      if (!polygon.holes.empty()) {
        at.fail(
            "the outer loop has no area (its vertices are collinear), so no hole can lie in it");
      }
      return polygon;
    }
    std::vector<std::string> warnings;
    Face face;
    try {
      face = detail::build_face(std::move(polygon), {face_id, file_, detail::FaceKind::kPolygon},
                                true, warnings);
    } catch (const InputError& e) {
      at.fail(e.problem());
    }
    warnings_.insert(warnings_.end(), warnings.begin(), warnings.end());
    return std::move(face.parts.front());
  }

  // lit['id']: the polygons, each on the part its "part" key names. Without the key (a
  // database written before parts were recorded) a polygon lies on the part whose plane
  // is nearest to its outer vertices, the first of equals.
  std::vector<LitPolygon> read_lit(const JsonValue& value, const Face& face,
                                   const detail::LitChecker& checker) const {
    const JsonArray list = value.array();
    std::vector<LitPolygon> out;
    out.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
      JsonObject object = list.at(k).object();
      LitPolygon lit{0, detail::read_polygon(object)};
      if (const std::optional<std::string> problem = detail::vertex_problem(lit.polygon)) {
        object.value().fail(*problem);
      }
      if (const std::optional<JsonValue> part = object.find("part")) {
        lit.part = part->index();
        if (lit.part >= face.parts.size()) {
          part->fail("expected the index of one of the face's " +
                     std::to_string(face.parts.size()) + " parts");
        }
      } else if (face.parts.size() > 1) {
        lit.part = checker.nearest_part(lit.polygon);
      }
      object.finish();
      out.push_back(std::move(lit));
    }
    if (const std::optional<detail::LitProblem> problem = checker.check(out)) {
      (problem->polygon ? list.at(*problem->polygon) : value).fail(problem->what);
    }
    return out;
  }

  const std::string file_;
  const ReadOptions options_;
  std::vector<std::string>& warnings_;
  detail::IdRegistry face_ids_;
  std::unordered_map<std::string, std::size_t> light_index_;
};

}  // namespace

ShadowedScene parse_database(const std::string& json_text, const std::filesystem::path& path,
                             const ReadOptions& options, std::vector<std::string>& warnings) {
  return DatabaseParser(path, options, warnings).run(json_text);
}

ShadowedScene read_database(const std::filesystem::path& path, const ReadOptions& options,
                            std::vector<std::string>& warnings) {
  return parse_database(read_text_file(path), path, options, warnings);
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
