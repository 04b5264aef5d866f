#include "shadowgen/output/obj_export.h"

#include <algorithm>
#include <glm/common.hpp>
#include <stdexcept>
#include <vector>

#include "detail/obj_text.h"
#include "detail/scene_regions.h"
#include "hsr/area.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/shadows/light_regions.h"

namespace shadowgen {
namespace {

using output::detail::LightSet;
using output::detail::LightSetNames;

std::string lights_comment(const Scene& scene, const LightSet& set) {
  if (set.empty()) return "# lights: none (shadow)\n";
  std::string out = "# lights:";
  for (const std::size_t l : set) {
    out += ' ';
    out += obj_name(scene.lights[l].id);
  }
  return out + '\n';
}

// One face's group: its "v" and "vn" lines, then a "usemtl" line per region and the
// region's triangles.
void append_face(std::string& obj, const Scene& scene, const Face& face,
                 const std::vector<LightRegion>& regions, const LightSetNames& names,
                 output::detail::ObjNumbering& numbering) {
  obj += "g ";
  obj += obj_name(face.id);
  obj += '\n';
  if (regions.empty()) return;
  output::detail::ObjFaceBlock block(face, numbering);
  for (const LightRegion& region : regions) {
    block.add_statement("usemtl", names.at(region.lights));
    if (!block.add_polygons(region.polygons)) {
      // Not the input's fault: valid regions always triangulate.
      throw GenerationError("", face.id, "",
                            "a region of light set '" + light_set_name(scene, region.lights) +
                                "' could not be split into triangles");
    }
  }
  block.append_to(obj, numbering);
}

// The MTL file: a header saying how the colours are made, then one material per set.
std::string mtl_text(const Scene& scene, const LightSetNames& names, std::string_view what) {
  std::string mtl = "# shadowgen MTL: ";
  mtl += what;
  mtl += ".\n# Kd = ";
  append_shortest(mtl, kAmbientGrey);
  mtl += " + ";
  append_shortest(mtl, 1.0 - kAmbientGrey);
  mtl += " * (intensity of the set's lights) / (intensity of all lights), per channel,\n";
  mtl += "# clamped to [0, 1]: the shadow is grey, a region every light reaches white.\n";
  for (const auto& [set, name] : names) {
    const glm::dvec3 colour = light_set_colour(scene, set);
    mtl += '\n';
    mtl += lights_comment(scene, set);
    output::detail::append_material(mtl, name, colour);
  }
  return mtl;
}

// A face's group name in the layers by light: obj_name() with '@' escaped as well, which
// separates it from the light's id.
std::string face_group_name(std::string_view id) {
  std::string out;
  for (const char c : obj_name(id)) {
    if (c == '@') {
      out += "%40";
    } else {
      out += c;
    }
  }
  return out;
}

// One face's block of layers by light: the face whole in shadow, then each light's lit
// polygons on it.
void append_face_layers(std::string& obj, const ShadowedScene& shadowed, std::size_t f,
                        const LightSetNames& names, output::detail::ObjNumbering& numbering) {
  const Scene& scene = shadowed.scene();
  const Face& face = scene.faces[f];
  const std::string group = face_group_name(face.id);
  obj += "g ";
  obj += group;
  obj += '\n';
  std::vector<LitPolygon> whole;
  for (std::size_t p = 0; p < face.parts.size(); ++p) {
    if (hsr::area(face.parts[p]) > 0.0) whole.push_back({p, face.parts[p]});
  }
  if (whole.empty()) return;
  output::detail::ObjFaceBlock block(face, numbering);
  block.add_statement("usemtl", names.at(LightSet{}));
  if (!block.add_polygons(whole)) {
    throw GenerationError("", face.id, "", "the face could not be split into triangles");
  }
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const LitTable::Polygons& lit = shadowed.lit().at(f, l);
    if (lit.empty()) continue;
    block.add_statement("g", group + "@" + obj_name(scene.lights[l].id));
    block.add_statement("usemtl", names.at(LightSet{l}));
    if (!block.add_polygons(lit)) {
      // Not the input's fault: valid lit polygons always triangulate.
      throw GenerationError("", face.id, scene.lights[l].id,
                            "its lit polygons could not be split into triangles");
    }
  }
  block.append_to(obj, numbering);
}

// Both files of an export: the OBJ's comment saying what it holds and its mtllib line,
// then each face's block as `append_face` writes it; the MTL of the materials `names`.
template <typename AppendFace>
ObjFiles export_files(const Scene& scene, std::string_view what, std::string_view mtl_file_name,
                      const LightSetNames& names, std::string_view materials,
                      AppendFace append_face) {
  ObjFiles files;
  std::string& obj = files.obj;
  obj += "# shadowgen OBJ export: ";
  obj += what;
  obj += "\nmtllib ";
  obj += mtl_file_name;
  obj += '\n';
  output::detail::ObjNumbering numbering;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) append_face(obj, f, numbering);
  files.mtl = mtl_text(scene, names, materials);
  return files;
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
  const Scene& scene = shadowed.scene();
  const output::detail::SceneRegions regions = output::detail::scene_regions(shadowed);
  const LightSetNames names = output::detail::light_set_names(scene, regions.sets, obj_name);
  return export_files(
      scene, "faces split by the set of lights reaching them", mtl_file_name, names,
      "one material per set of lights reaching a region",
      [&](std::string& obj, std::size_t f, output::detail::ObjNumbering& numbering) {
        append_face(obj, scene, scene.faces[f], regions.of_face[f], names, numbering);
      });
}

ObjFiles obj_export_by_light(const ShadowedScene& shadowed, std::string_view mtl_file_name) {
  const Scene& scene = shadowed.scene();
  output::detail::LightSets sets = {LightSet{}};
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      if (!shadowed.lit().at(f, l).empty()) sets.insert(LightSet{l});
    }
  }
  const LightSetNames names = output::detail::light_set_names(scene, sets, obj_name);
  return export_files(
      scene, "each face in shadow, each light's lit polygons over it", mtl_file_name, names,
      "the shadow, then one material per light reaching a face",
      [&](std::string& obj, std::size_t f, output::detail::ObjNumbering& numbering) {
        append_face_layers(obj, shadowed, f, names, numbering);
      });
}

}  // namespace shadowgen
