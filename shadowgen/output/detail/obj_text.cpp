#include "detail/obj_text.h"

#include <optional>

#include "clipper/predicates.h"
#include "clipper/triangulate.h"
#include "hsr/plane_chart.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::detail {

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
    const hsr::PlaneChart chart = hsr::chart_facing(plane_normal);
    const hsr::Polygon3& polygon = lit.polygon;
    std::vector<glm::dvec3> corners(polygon.outer);
    std::vector<clipper::Loop2> loops{chart.flatten(polygon.outer)};
    for (const hsr::Loop3& h : polygon.holes) {
      loops.push_back(chart.flatten(h));
      corners.insert(corners.end(), h.begin(), h.end());
    }
    std::vector<clipper::Point2> flat;
    for (const clipper::Loop2& loop : loops) flat.insert(flat.end(), loop.begin(), loop.end());
    const std::optional<std::vector<clipper::Triangle>> triangles = clipper::triangulate(loops);
    if (!triangles) return false;
    for (const clipper::Triangle& t : *triangles) {
      if (clipper::orient2d(flat[t[0]], flat[t[1]], flat[t[2]]) ==
          clipper::Orientation::kCollinear) {
        continue;  // no area
      }
      lines_ += 'f';
      for (const std::size_t corner : t) {
        lines_ += ' ';
        lines_ += std::to_string(vertex(corners[corner]) + 1);
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

}  // namespace shadowgen::detail
