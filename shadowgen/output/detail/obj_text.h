#pragma once

// The OBJ and MTL text that every OBJ export writes the same way (shadowgen/output/
// obj_export.h: faces by light set; sun_hours_export.h: faces by band of sun hours): one
// face's block of vertices, normals and triangles, and one material.

#include <cstddef>
#include <glm/vec3.hpp>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::output::detail {

// "<tag> x y z\n", the numbers in their shortest round-trip form.
void append_vector(std::string& out, std::string_view tag, const glm::dvec3& v);

// A material of one colour: "newmtl", Ka and Kd the colour, Ks 0 0 0, d 1, illum 1.
void append_material(std::string& mtl, std::string_view name, const glm::dvec3& colour);

// How many vertices and normals the OBJ has numbered so far.
struct ObjNumbering {
  std::size_t vertices = 0;
  std::size_t normals = 0;
};

// One face's block: its "v" and "vn" lines, then the statements and triangles added, in
// the order added. Vertices and normals are shared within the face only when bit-equal
// (up to the sign of zero), numbered globally on from the numbering given and not shared
// with other faces.
class ObjFaceBlock {
 public:
  ObjFaceBlock(const Face& face, const ObjNumbering& numbering);

  // "<tag> <name>\n": a group ("g") or a material ("usemtl").
  void add_statement(std::string_view tag, std::string_view name);

  // The "f" lines of `polygons`: each triangulated in the plane chart of the part it lies
  // on by ear clipping (clipper/triangulate.h) on its own 3D vertices, no point added,
  // counter-clockwise seen from the front, triangles without area left out. False when a
  // polygon could not be split into triangles (valid regions always are).
  bool add_polygons(std::span<const LitPolygon> polygons);

  // Appends the block to `obj` and advances `numbering` past its vertices and normals.
  void append_to(std::string& obj, ObjNumbering& numbering) const;

 private:
  using Key = std::tuple<double, double, double>;
  std::size_t vertex(const glm::dvec3& p);
  std::size_t normal(const glm::dvec3& n);

  ObjNumbering first_;
  std::vector<glm::dvec3> part_normals_;  // by the index of the face's part
  std::map<Key, std::size_t> vertices_, normals_;
  std::vector<glm::dvec3> vertex_list_, normal_list_;
  std::string lines_;  // the statements and "f" lines, after the "v" and "vn" lines
};

}  // namespace shadowgen::output::detail
