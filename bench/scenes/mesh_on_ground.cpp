#include "bench/scenes/mesh_on_ground.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <stdexcept>
#include <string>

#include "shadowgen/json/json_text.h"
#include "shadowgen/scene/scene_reader.h"

namespace shadowgen::bench {
namespace {

constexpr double kGap = 0.02;

using Matrix = double[4][4];

// The mesh read through `transform` (row-major 4 × 4, as the format writes it), after the
// polygons and lights of `rest` (JSON members, each with a leading comma).
Scene read(const std::filesystem::path& mesh, const Matrix& transform, const std::string& rest) {
  std::string text = R"({"format": "shadowgen-scene/1", "meshes": [{"id": "mesh", "file": )";
  json::detail::append_json_string(text, std::filesystem::absolute(mesh).string());
  text += R"(, "transform": [)";
  for (int r = 0; r < 4; ++r) {
    text += r ? ", [" : "[";
    for (int c = 0; c < 4; ++c) {
      if (c) text += ", ";
      json::detail::append_json_number(text, transform[r][c]);
    }
    text += "]";
  }
  text += "]}]" + rest + "}";
  return parse_scene(text, std::filesystem::absolute(mesh).parent_path() / "mesh_on_ground.json")
      .scene;
}

}  // namespace

Scene mesh_on_ground(const std::filesystem::path& mesh, UpAxis up) {
  // A y-up file is turned a quarter about x, (x, y, z) -> (x, -z, y): a rotation, so the
  // faces keep their front sides.
  Matrix turn = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  if (up == UpAxis::kY) {
    turn[1][1] = 0.0;
    turn[1][2] = -1.0;
    turn[2][1] = 1.0;
    turn[2][2] = 0.0;
  }
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Face& face : read(mesh, turn, "").faces) {
    for (const hsr::Polygon3& part : face.parts) {
      for (const glm::dvec3& v : part.outer) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
    }
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(extent > 0.0)) throw std::runtime_error("mesh without extent: " + mesh.string());
  const double s = 1.0 / extent;
  const glm::dvec3 shift(-0.5 * (lo.x + hi.x) * s, -0.5 * (lo.y + hi.y) * s, kGap - lo.z * s);
  Matrix place;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) place[r][c] = r < 3 ? s * turn[r][c] : turn[r][c];
  }
  for (int r = 0; r < 3; ++r) place[r][3] = shift[r];
  return read(mesh, place, R"(,
    "polygons": [{"id": "ground", "outer": [[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]]}],
    "lights": [
      {"id": "sun", "type": "directional", "direction": [-0.5, 0.35, -1]},
      {"id": "lamp", "type": "point", "position": [0.7, -0.55, 1.2], "intensity": [1, 1, 1]}
    ])");
}

}  // namespace shadowgen::bench
