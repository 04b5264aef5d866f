#include "detail/mesh_entry.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <utility>

#include "detail/face_builder.h"
#include "detail/mesh_reader.h"
#include "detail/referenced_file.h"
#include "detail/source_format.h"
#include "detail/source_readers.h"
#include "detail/warning_summary.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::scene::detail {
namespace {

// Row-major 4x4, applied to column vectors (x, y, z, 1); the last row gives w.
using Transform = std::array<std::array<double, 4>, 4>;

Transform transform_of(const JsonValue& value) {
  if (!value.is_array() || value.array().size() != 4) value.fail("expected 4 rows of 4 numbers");
  const JsonArray rows = value.array();
  Transform m{};
  for (std::size_t r = 0; r < 4; ++r) {
    const JsonValue row_value = rows.at(r);
    if (!row_value.is_array() || row_value.array().size() != 4) {
      row_value.fail("expected a row of 4 numbers");
    }
    const JsonArray row = row_value.array();
    for (std::size_t c = 0; c < 4; ++c) m[r][c] = row.at(c).number();
  }
  return m;
}

std::string number_text(double value) {
  std::ostringstream s;
  s.precision(17);
  s << value;
  return s.str();
}

struct PlacedVertex {
  glm::dvec3 p{0.0};
  double w = 1.0;  // 0 or not finite: the transform sends the vertex to infinity
  bool finite = true;
};

PlacedVertex place(const Transform& m, const glm::dvec3& v) {
  auto row = [&](std::size_t r) { return m[r][0] * v.x + m[r][1] * v.y + m[r][2] * v.z + m[r][3]; };
  PlacedVertex out;
  out.p = glm::dvec3(row(0), row(1), row(2));
  const bool affine = m[3][0] == 0.0 && m[3][1] == 0.0 && m[3][2] == 0.0 && m[3][3] == 1.0;
  if (!affine) {
    out.w = row(3);
    if (std::isfinite(out.w) && out.w != 0.0) out.p /= out.w;
  }
  out.finite = std::isfinite(out.w) && out.w != 0.0 && std::isfinite(out.p.x) &&
               std::isfinite(out.p.y) && std::isfinite(out.p.z);
  return out;
}

// Face record k of the soup as a polygon in scene coordinates. Throws InputError naming
// the mesh file and the face.
hsr::Polygon3 face_polygon(const MeshFaceRecord& record, const std::vector<PlacedVertex>& placed,
                           const std::string& mesh_file, const std::string& face_id) {
  const std::string at_line = record.line > 0 ? " (line " + std::to_string(record.line) + ")" : "";
  auto fail = [&](const std::string& what) {
    throw InputError(mesh_file, face_id, what + at_line);
  };
  if (record.vertices.size() < 3) {
    fail("the face record has " + std::to_string(record.vertices.size()) +
         " vertex indices; at least 3 are needed");
  }
  hsr::Polygon3 polygon;
  polygon.outer.reserve(record.vertices.size());
  int w_sign = 0;
  for (const std::int64_t index : record.vertices) {
    if (index < 0 || static_cast<std::uint64_t>(index) >= placed.size()) {
      fail("vertex index " + std::to_string(index) + " (counting from 0) is out of range: " +
           "the file has " + std::to_string(placed.size()) + " vertices");
    }
    const PlacedVertex& v = placed[static_cast<std::size_t>(index)];
    if (!v.finite) {
      fail("the mesh transform sends vertex " + std::to_string(index) +
           " to infinity (w = " + number_text(v.w) + ")");
    }
    const int sign = v.w > 0.0 ? 1 : -1;
    if (w_sign != 0 && sign != w_sign) {
      fail(
          "the projective mesh transform splits the face across infinity (w changes sign "
          "between its vertices)");
    }
    w_sign = sign;
    polygon.outer.push_back(v.p);
  }
  return polygon;
}

// An upper bound of how far an affine transform stretches any length: the Frobenius norm
// of its linear part. nullopt for a projective transform, which stretches without bound
// near its plane at infinity.
std::optional<double> stretch_of(const std::optional<Transform>& transform) {
  if (!transform) return 1.0;
  const Transform& m = *transform;
  if (m[3][0] != 0.0 || m[3][1] != 0.0 || m[3][2] != 0.0 || m[3][3] != 1.0) return std::nullopt;
  double sum = 0.0;
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) sum += m[r][c] * m[r][c];
  }
  return std::sqrt(sum);
}

hsr::Loop3 placed_loop(const hsr::Loop3& loop, const Transform& transform, const std::string& file,
                       const std::string& face_id) {
  hsr::Loop3 out;
  out.reserve(loop.size());
  int w_sign = 0;
  for (const glm::dvec3& p : loop) {
    const PlacedVertex v = place(transform, p);
    if (!v.finite) {
      throw InputError(
          file, face_id,
          "the mesh transform sends a vertex to infinity (w = " + number_text(v.w) + ")");
    }
    const int sign = v.w > 0.0 ? 1 : -1;
    if (w_sign != 0 && sign != w_sign) {
      throw InputError(file, face_id,
                       "the projective mesh transform splits the face across infinity (w "
                       "changes sign between its vertices)");
    }
    w_sign = sign;
    out.push_back(v.p);
  }
  return out;
}

// The faces of a model file of another tool, as its room gave them.
void add_source_faces(SourceModel& model, const std::string& id,
                      const std::optional<Transform>& transform, const std::string& file,
                      const ReadOptions& options, std::vector<Face>& faces,
                      std::vector<std::string>& warnings) {
  if (model.faces.empty()) {
    throw InputError(file, "", "model '" + id + "' has no faces");
  }
  const std::optional<double> stretch = stretch_of(transform);
  WarningSummary summary(file, "faces of model '" + id + "'");
  std::vector<std::string> face_warnings;
  for (SourceFace& source : model.faces) {
    const std::string face_id = id + "/" + source.id;
    hsr::Polygon3 polygon = std::move(source.polygon);
    if (transform) {
      polygon.outer = placed_loop(polygon.outer, *transform, file, face_id);
      for (hsr::Loop3& hole : polygon.holes) hole = placed_loop(hole, *transform, file, face_id);
    }
    const FaceSource face_source{face_id, file, FaceKind::kMeshFace,
                                 stretch ? source.vertex_rounding * *stretch : 0.0,
                                 std::move(source.origin)};
    faces.push_back(build_face(std::move(polygon), face_source, options.strict, face_warnings));
    for (std::string& line : face_warnings) summary.add(face_id, std::move(line));
    face_warnings.clear();
  }
  summary.append_to(warnings, options.verbose);
  warnings.insert(warnings.end(), model.warnings.begin(), model.warnings.end());
}

// The entry's "lod": a string, or a number written as its shortest decimal form.
std::string lod_of(const JsonValue& value) {
  if (value.describe() == "a number") return shortest(value.number());
  return value.string();
}

}  // namespace

MeshEntryRead read_mesh_entry(const JsonValue& value, const std::filesystem::path& scene_path,
                              const ReadOptions& options, IdRegistry& ids, std::vector<Face>& faces,
                              std::vector<std::string>& warnings) {
  JsonObject entry = value.object();
  const std::string id = read_id(entry);
  ids.claim(id, "mesh '" + id + "'", entry.get("id"));
  entry.name("mesh '" + id + "'", id);
  const JsonValue file_value = entry.get("file");
  std::optional<Transform> transform;
  if (const std::optional<JsonValue> t = entry.find("transform")) transform = transform_of(*t);
  const std::optional<JsonValue> lod = entry.find("lod");
  SourceOptions source_options{options.strict, {}};
  if (lod) source_options.lod = lod_of(*lod);
  entry.finish();

  const std::filesystem::path mesh_path = referenced_file(file_value, scene_path, "mesh file");
  const std::string mesh_file = mesh_path.string();
  const SourceFormat format = format_of_file(mesh_path);
  if (lod && format != SourceFormat::kCityJson) {
    lod->fail("'lod' chooses a CityJSON file's level of detail; '" + mesh_file + "' is " +
              std::string(format_name(format)));
  }
  if (format != SourceFormat::kMesh) {
    SourceModel model = read_source(format, mesh_path, source_options);
    add_source_faces(model, id, transform, mesh_file, options, faces, warnings);
    return {mesh_file, std::move(model.site)};
  }
  const MeshSoup soup = read_mesh(mesh_path, id);
  if (soup.faces.empty()) {
    warnings.push_back(face_message(mesh_file, "", "mesh '" + id + "' has no faces"));
  }
  std::vector<PlacedVertex> placed(soup.vertices.size());
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    placed[v] = transform ? place(*transform, soup.vertices[v]) : PlacedVertex{soup.vertices[v]};
  }
  WarningSummary summary(mesh_file, "faces of mesh '" + id + "'");
  std::vector<std::string> face_warnings;
  for (std::size_t k = 0; k < soup.faces.size(); ++k) {
    const std::string face_id = id + "/" + std::to_string(k);
    faces.push_back(build_face(face_polygon(soup.faces[k], placed, mesh_file, face_id),
                               {face_id, mesh_file, FaceKind::kMeshFace}, options.strict,
                               face_warnings));
    for (std::string& line : face_warnings) summary.add(face_id, std::move(line));
    face_warnings.clear();
  }
  summary.append_to(warnings, options.verbose);
  return {mesh_file, {}};
}

}  // namespace shadowgen::scene::detail
