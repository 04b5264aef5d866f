#include "detail/cityjson_seq.h"

#include <string_view>

#include "detail/city_objects.h"
#include "detail/cityjson_header.h"
#include "detail/extension_keys.h"
#include "detail/model_site.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::cityjson::detail {
namespace {

constexpr std::string_view kFirstLine = "line 1, column ";

bool blank(std::string_view line) {
  return line.find_first_not_of(" \t\r\n") == std::string_view::npos;
}

// Runs `read` on what line `line` holds, its errors and warnings said of that line.
template <typename Read>
void on_line_of(const std::string& file, std::size_t line, std::vector<std::string>& warnings,
                Read read) {
  std::vector<std::string> line_warnings;
  try {
    read(line_warnings);
  } catch (const InputError& e) {
    throw InputError(e.file(), e.face_id(), on_line(e.problem(), line));
  }
  const std::string prefix = file + ": ";
  for (std::string& w : line_warnings) {
    warnings.push_back(w.starts_with(prefix) ? prefix + on_line(w.substr(prefix.size()), line)
                                             : std::move(w));
  }
}

}  // namespace

std::string on_line(const std::string& problem, std::size_t line) {
  if (std::string_view(problem).starts_with(kFirstLine)) {
    return "line " + std::to_string(line) + ", column " + problem.substr(kFirstLine.size());
  }
  return "line " + std::to_string(line) + ": " + problem;
}

SourceModel read_cityjson_seq(const std::string& first, std::size_t next_line, std::istream& in,
                              const std::string& file, const SourceOptions& options) {
  SourceModel model;
  CityJsonHeader header;
  on_line_of(file, 1, model.warnings, [&](std::vector<std::string>& line_warnings) {
    const JsonDocument document(first, {file, options.strict, &line_warnings});
    JsonObject top = document.root().object();
    header = read_header(top);
    if (!header.transform) {
      top.value().fail(
          "missing 'transform': a CityJSONSeq file's first line needs one, its features' "
          "vertices are integers it scales");
    }
    const JsonValue objects = top.get("CityObjects");
    if (objects.object().size() != 0) {
      objects.fail(
          "must be empty in a CityJSONSeq file's first line: the city objects come one "
          "feature a line after it");
    }
    const JsonValue vertices = top.get("vertices");
    if (!vertices.array().empty()) {
      vertices.fail("must be empty in a CityJSONSeq file's first line: each feature has its own");
    }
    finish_allowing_extension_keys(top);
  });

  CityObjectFaces faces(file, options);
  const GeometryTemplates* templates = header.templates ? &*header.templates : nullptr;
  std::string text;
  for (std::size_t line = next_line; std::getline(in, text); ++line) {
    if (blank(text)) continue;
    on_line_of(file, line, model.warnings, [&](std::vector<std::string>& line_warnings) {
      const JsonDocument document(text, {file, options.strict, &line_warnings});
      JsonObject feature = document.root().object();
      const JsonValue type = feature.get("type");
      if (const std::string name = type.string(); name != "CityJSONFeature") {
        type.fail("expected a CityJSONFeature, found '" + name +
                  "': after its first line a CityJSONSeq file holds one feature a line");
      }
      feature.get("id").string();
      const VertexList vertices = read_vertices(feature.get("vertices"), &*header.transform);
      const GeometryVertices geometry_vertices{
          &vertices.points, {vertices.points.size(), "the feature has"}, vertices.rounding()};
      faces.read(feature.get("CityObjects"), geometry_vertices, templates, line);
      feature.has("appearance");
      finish_allowing_extension_keys(feature);
    });
  }
  if (in.bad()) throw InputError(file, "", "could not be read to its end");
  faces.finish(model.warnings);
  model.faces = std::move(faces.faces());
  if (header.crs) derive_site(*header.crs, faces.bounds(), file, model);
  return model;
}

}  // namespace shadowgen::cityjson::detail
