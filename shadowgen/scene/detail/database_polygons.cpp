#include "database_polygons.h"

#include <optional>
#include <utility>

#include "coordinate_range.h"
#include "face_builder.h"
#include "hsr/collinearity.h"
#include "indexed_polygons.h"
#include "json_entities.h"
#include "lit_checks.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

namespace key = database::key;

hsr::Polygon3 checked_database_part(hsr::Polygon3 polygon, const JsonValue& at,
                                    const FaceSource& source, std::vector<std::string>& warnings) {
  if (const std::optional<std::string> problem = coordinate_problem(polygon)) {
    at.fail(*problem);
  }
  if (polygon.outer.size() >= 3 &&
      (hsr::distinct_points_up_to_3(polygon.outer) < 3 || hsr::all_collinear(polygon.outer))) {
    if (!polygon.holes.empty()) {
      at.fail("the outer loop has no area (its vertices are collinear), so no hole can lie in it");
    }
    return polygon;
  }
  std::vector<std::string> built_warnings;
  Face face;
  try {
    face = build_face(std::move(polygon), source, true, built_warnings);
  } catch (const InputError& e) {
    at.fail(e.problem());
  }
  warnings.insert(warnings.end(), built_warnings.begin(), built_warnings.end());
  return std::move(face.parts.front());
}

std::vector<LitPolygon> read_database_lit(const JsonValue& value, const Face& face,
                                          const LitLayout& layout) {
  const JsonArray list = value.array();
  if (layout.layout == database::Layout::kIndexed) {
    std::vector<LitPolygon> out;
    out.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
      out.push_back(read_indexed_lit(list.at(k), layout.vertices, face.parts.size()));
    }
    return out;
  }
  std::optional<LitChecker> checker;  // only to place polygons without "part"
  std::vector<LitPolygon> out;
  out.reserve(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) {
    JsonObject object = list.at(k).object();
    LitPolygon lit{0, read_polygon(object)};
    if (const std::optional<std::string> problem = vertex_problem(lit.polygon)) {
      object.value().fail(*problem);
    }
    if (const std::optional<JsonValue> part = object.find(key::kPart)) {
      lit.part = part->index();
      if (lit.part >= face.parts.size()) {
        part->fail("expected the index of one of the face's " + std::to_string(face.parts.size()) +
                   " parts");
      }
    } else if (face.parts.size() > 1) {
      if (!checker) checker.emplace(face);
      lit.part = checker->nearest_part(lit.polygon);
    }
    object.finish();
    out.push_back(std::move(lit));
  }
  return out;
}

}  // namespace shadowgen::scene::detail
