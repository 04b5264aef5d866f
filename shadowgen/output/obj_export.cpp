#include "shadowgen/output/obj_export.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <glm/geometric.hpp>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "clipper/predicates.h"
#include "clipper/triangulate.h"
#include "hsr/area.h"
#include "hsr/plane_chart.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/shadows/light_regions.h"

namespace shadowgen {
namespace {

using LightSet = std::vector<std::size_t>;

void append_vector(std::string& out, std::string_view tag, const glm::dvec3& v) {
  out += tag;
  for (int i = 0; i < 3; ++i) {
    out += ' ';
    append_shortest(out, v[i]);
  }
  out += '\n';
}

// Exact-value keys: vertices and normals are shared within a face only when bit-equal
// (up to the sign of zero).
using Key = std::tuple<double, double, double>;
Key key_of(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// One face's vertices and normals, numbered globally from `first_vertex` and
// `first_normal` (0-based here, printed 1-based).
class FaceBlock {
 public:
  FaceBlock(std::size_t first_vertex, std::size_t first_normal)
      : first_vertex_(first_vertex), first_normal_(first_normal) {}

  std::size_t vertex(const glm::dvec3& p) {
    const auto [it, added] = vertices_.emplace(key_of(p), first_vertex_ + vertex_list_.size());
    if (added) vertex_list_.push_back(p);
    return it->second;
  }
  std::size_t normal(const glm::dvec3& n) {
    const auto [it, added] = normals_.emplace(key_of(n), first_normal_ + normal_list_.size());
    if (added) normal_list_.push_back(n);
    return it->second;
  }

  const std::vector<glm::dvec3>& vertex_list() const { return vertex_list_; }
  const std::vector<glm::dvec3>& normal_list() const { return normal_list_; }

 private:
  std::size_t first_vertex_, first_normal_;
  std::map<Key, std::size_t> vertices_, normals_;
  std::vector<glm::dvec3> vertex_list_, normal_list_;
};

// Material names, one per light set, unique.
std::map<LightSet, std::string, LightSetLess> material_names(
    const Scene& scene, const std::set<LightSet, LightSetLess>& sets) {
  std::map<LightSet, std::string, LightSetLess> names;
  std::set<std::string> taken;
  for (const LightSet& s : sets) {
    const std::string base = obj_name(light_set_name(scene, s));
    std::string name = base;
    for (int k = 2; taken.count(name) != 0; ++k) name = base + "~" + std::to_string(k);
    taken.insert(name);
    names.emplace(s, name);
  }
  return names;
}

std::string lights_comment(const Scene& scene, const LightSet& set) {
  if (set.empty()) return "# lights: none (shadow)\n";
  std::string out = "# lights:";
  for (const std::size_t l : set) {
    out += ' ';
    out += obj_name(scene.lights[l].id);
  }
  return out + '\n';
}

// The regions of every face by light set, and the light sets that occur.
struct SceneRegions {
  std::vector<std::vector<LightRegion>> of_face;
  std::set<LightSet, LightSetLess> sets;
};

SceneRegions scene_regions(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene;
  if (shadowed.lit.size() != scene.faces.size()) {
    throw std::invalid_argument("obj_export: lit detail polygons not shaped [face][light]");
  }
  SceneRegions regions;
  regions.of_face.resize(scene.faces.size());
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    regions.of_face[f] = light_regions(shadowed, f);
    for (const LightRegion& r : regions.of_face[f]) regions.sets.insert(r.lights);
  }
  return regions;
}

// The "f" lines of one lit polygon: its triangles in `chart`, the chart of the part it
// lies on (those without area there left out), on the polygon's own 3D vertices, all with
// normal number `normal`. False when it could not be split into triangles.
bool append_triangles(std::string& faces, FaceBlock& block, const hsr::Polygon3& polygon,
                      const hsr::PlaneChart& chart, std::size_t normal) {
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
    if (clipper::orient2d(flat[t[0]], flat[t[1]], flat[t[2]]) == clipper::Orientation::kCollinear) {
      continue;  // no area
    }
    faces += 'f';
    for (const std::size_t corner : t) {
      faces += ' ';
      faces += std::to_string(block.vertex(corners[corner]) + 1);
      faces += "//";
      faces += std::to_string(normal + 1);
    }
    faces += '\n';
  }
  return true;
}

// One face's group: its "v" and "vn" lines, then a "usemtl" line per region and the
// region's triangles. Vertices and normals are numbered on from the counts given, which
// are advanced past the face's own.
void append_face(std::string& obj, const Scene& scene, const Face& face,
                 const std::vector<LightRegion>& regions,
                 const std::map<LightSet, std::string, LightSetLess>& names,
                 std::size_t& vertex_count, std::size_t& normal_count) {
  obj += "g ";
  obj += obj_name(face.id);
  obj += '\n';
  if (regions.empty()) return;
  std::vector<hsr::Plane3> planes;  // by the index of the face's part
  for (const hsr::Polygon3& p : face.parts) planes.push_back(hsr::plane_of(p));
  FaceBlock block(vertex_count, normal_count);
  std::string faces;  // the usemtl and f lines, after the face's v and vn lines
  for (const LightRegion& region : regions) {
    faces += "usemtl ";
    faces += names.at(region.lights);
    faces += '\n';
    for (const LitPolygon& lit : region.polygons) {
      const hsr::Plane3& plane = planes[lit.part];
      const std::size_t normal = block.normal(plane.normal);
      if (!append_triangles(faces, block, lit.polygon, hsr::chart_facing(plane.normal), normal)) {
        // Not the input's fault: valid regions always triangulate.
        throw GenerationError("", face.id, "",
                              "a region of light set '" + light_set_name(scene, region.lights) +
                                  "' could not be split into triangles");
      }
    }
  }
  for (const glm::dvec3& v : block.vertex_list()) append_vector(obj, "v", v);
  for (const glm::dvec3& v : block.normal_list()) append_vector(obj, "vn", v);
  obj += faces;
  vertex_count += block.vertex_list().size();
  normal_count += block.normal_list().size();
}

// The MTL file: a header saying how the colours are made, then one material per set.
std::string mtl_text(const Scene& scene,
                     const std::map<LightSet, std::string, LightSetLess>& names) {
  std::string mtl = "# shadowgen MTL: one material per set of lights reaching a region.\n# Kd = ";
  append_shortest(mtl, kAmbientGrey);
  mtl += " + ";
  append_shortest(mtl, 1.0 - kAmbientGrey);
  mtl += " * (intensity of the set's lights) / (intensity of all lights), per channel,\n";
  mtl += "# clamped to [0, 1]: the shadow is grey, a region every light reaches white.\n";
  for (const auto& [set, name] : names) {
    const glm::dvec3 colour = light_set_colour(scene, set);
    mtl += '\n';
    mtl += lights_comment(scene, set);
    mtl += "newmtl ";
    mtl += name;
    mtl += '\n';
    append_vector(mtl, "Ka", colour);
    append_vector(mtl, "Kd", colour);
    mtl += "Ks 0 0 0\nd 1\nillum 1\n";
  }
  return mtl;
}

}  // namespace

std::string obj_name(std::string_view name) {
  if (name.empty()) return "%";
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  out.reserve(name.size());
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte <= 0x20 || byte >= 0x7f || c == '#' || c == '%') {
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

glm::dvec3 light_set_colour(const Scene& scene, std::span<const std::size_t> lights) {
  glm::dvec3 total(0.0), in_set(0.0);
  for (const Light& light : scene.lights) total += glm::max(light.intensity, glm::dvec3(0.0));
  for (const std::size_t l : lights) {
    in_set += glm::max(scene.lights.at(l).intensity, glm::dvec3(0.0));
  }
  glm::dvec3 colour(kAmbientGrey);
  for (int c = 0; c < 3; ++c) {
    if (total[c] > 0.0) colour[c] += (1.0 - kAmbientGrey) * in_set[c] / total[c];
    colour[c] = std::clamp(colour[c], 0.0, 1.0);
  }
  return colour;
}

ObjFiles obj_export(const ShadowedScene& shadowed, std::string_view mtl_file_name) {
  const Scene& scene = shadowed.scene;
  const SceneRegions regions = scene_regions(shadowed);
  const std::map<LightSet, std::string, LightSetLess> names = material_names(scene, regions.sets);

  ObjFiles files;
  std::string& obj = files.obj;
  obj += "# shadowgen OBJ export: faces split by the set of lights reaching them\n";
  obj += "mtllib ";
  obj += mtl_file_name;
  obj += '\n';
  std::size_t vertex_count = 0, normal_count = 0;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    append_face(obj, scene, scene.faces[f], regions.of_face[f], names, vertex_count, normal_count);
  }
  files.mtl = mtl_text(scene, names);
  return files;
}

}  // namespace shadowgen
