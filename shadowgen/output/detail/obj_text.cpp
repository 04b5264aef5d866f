#include "detail/obj_text.h"

#include <optional>

#include "hsr/chart_triangles.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::output::detail {

void append_vector(std::string& out, std::string_view tag, const glm::dvec3& v) {
  out += tag;
  for (int i = 0; i < 3; ++i) {
    out += ' ';
    append_shortest(out, v[i]);
  }
  out += '\n';
}

void append_material(std::string& mtl, std::string_view name, const glm::dvec3& colour) {
  mtl += "newmtl ";
  mtl += name;
  mtl += '\n';
  append_vector(mtl, "Ka", colour);
  append_vector(mtl, "Kd", colour);
  mtl += "Ks 0 0 0\nd 1\nillum 1\n";
}

ObjFaceBlock::ObjFaceBlock(const Face& face, const ObjNumbering& numbering) : first_(numbering) {
  for (const hsr::Polygon3& p : face.parts) part_normals_.push_back(hsr::plane_of(p).normal);
}

void ObjFaceBlock::add_statement(std::string_view tag, std::string_view name) {
  lines_ += tag;
  lines_ += ' ';
  lines_ += name;
  lines_ += '\n';
}

bool ObjFaceBlock::add_polygons(std::span<const LitPolygon> polygons) {
  for (const LitPolygon& lit : polygons) {
    const glm::dvec3& plane_normal = part_normals_.at(lit.part);
    const std::size_t n = normal(plane_normal);
    const std::optional<hsr::ChartTriangles> split =
        hsr::tiled_chart_triangles(lit.polygon, plane_normal);
    if (!split) return false;
    for (std::size_t k = 0; k < split->triangles.size(); ++k) {
      if (split->flat_triangle(k)) continue;  // no area
      const clipper::Triangle& t = split->triangles[k];
      lines_ += 'f';
      for (const std::size_t corner : t) {
        lines_ += ' ';
        lines_ += std::to_string(vertex(split->corners[corner]) + 1);
        lines_ += "//";
        lines_ += std::to_string(n + 1);
      }
      lines_ += '\n';
    }
  }
  return true;
}

void ObjFaceBlock::append_to(std::string& obj, ObjNumbering& numbering) const {
  for (const glm::dvec3& v : vertex_list_) append_vector(obj, "v", v);
  for (const glm::dvec3& v : normal_list_) append_vector(obj, "vn", v);
  obj += lines_;
  numbering.vertices += vertex_list_.size();
  numbering.normals += normal_list_.size();
}

std::size_t ObjFaceBlock::vertex(const glm::dvec3& p) {
  const auto [it, added] =
      vertices_.emplace(Key{p.x, p.y, p.z}, first_.vertices + vertex_list_.size());
  if (added) vertex_list_.push_back(p);
  return it->second;
}

std::size_t ObjFaceBlock::normal(const glm::dvec3& n) {
  const auto [it, added] =
      normals_.emplace(Key{n.x, n.y, n.z}, first_.normals + normal_list_.size());
  if (added) normal_list_.push_back(n);
  return it->second;
}

}  // namespace shadowgen::output::detail
