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
#include "detail/warning_summary.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::detail {
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

}  // namespace

std::string read_mesh_entry(const JsonValue& value, const std::filesystem::path& scene_path,
                            const ReadOptions& options, IdRegistry& ids, std::vector<Face>& faces,
                            std::vector<std::string>& warnings) {
  JsonObject entry = value.object();
  const std::string id = read_id(entry);
  ids.claim(id, "mesh '" + id + "'", entry.get("id"));
  entry.name("mesh '" + id + "'", id);
  const JsonValue file_value = entry.get("file");
  std::optional<Transform> transform;
  if (const std::optional<JsonValue> t = entry.find("transform")) transform = transform_of(*t);
  entry.finish();

  const std::filesystem::path mesh_path = referenced_file(file_value, scene_path, "mesh file");
  const MeshSoup soup = read_mesh(mesh_path, id);
  const std::string mesh_file = mesh_path.string();
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
  return mesh_file;
}

}  // namespace shadowgen::detail
