#include "detail/city_objects.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "detail/extension_keys.h"
#include "detail/geometry_templates.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen::cityjson::detail {

void Bounds::add(const glm::dvec3& p) {
  if (empty) {
    low = high = p;
    empty = false;
    return;
  }
  low = glm::min(low, p);
  high = glm::max(high, p);
}

struct CityObjectFaces::Object {
  std::string id;
  std::optional<std::string> parent;  // the first of "parents"
  std::vector<Geometry> geometries;
};

namespace {

// The keys CityJSON defines for a city object, besides "type", "geometry" and "parents"
// (versions 1.0 to 2.0): none of them places a surface.
constexpr const char* kOtherObjectKeys[] = {"attributes", "geographicalExtent", "children",
                                            "address", "children_roles"};

// The geometries of `geometries` chosen by `asked` (SourceOptions::lod), or else of the
// highest level among those that bound surfaces; their indices, in order.
std::vector<std::size_t> chosen_geometries(const std::vector<Geometry>& geometries,
                                           const GeometryTemplates* templates,
                                           const std::optional<std::string>& asked) {
  auto bounds_any_surface = [&](const Geometry& g) {
    if (g.placement) return bounds_surfaces(templates->templates[g.placement->template_index].type);
    return bounds_surfaces(g.type);
  };
  std::optional<Lod> chosen;
  if (!asked) {
    for (const Geometry& g : geometries) {
      if (bounds_any_surface(g) && (!chosen || g.lod.value > chosen->value)) chosen = g.lod;
    }
    if (!chosen) return {};
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < geometries.size(); ++i) {
    const Geometry& g = geometries[i];
    if (!bounds_any_surface(g)) continue;
    if (asked ? g.lod.matches(*asked) : g.lod.text == chosen->text) out.push_back(i);
  }
  return out;
}

std::string list_of(const std::set<std::string>& texts) {
  std::string out;
  for (const std::string& t : texts) out += (out.empty() ? "" : ", ") + t;
  return out;
}

}  // namespace

CityObjectFaces::CityObjectFaces(std::string file, const SourceOptions& options)
    : file_(std::move(file)), options_(options) {}

void CityObjectFaces::read(const JsonValue& city_objects, const GeometryVertices& vertices,
                           const GeometryTemplates* templates, std::size_t line) {
  std::vector<Object> objects;
  std::map<std::string, std::optional<std::string>> parents;
  for (auto& [id, value] : city_objects.object().entries()) {
    if (line > 0) {
      const auto [at, inserted] = lines_of_ids_.emplace(id, line);
      if (!inserted) {
        value.fail("city object '" + id + "' is given again (first on line " +
                   std::to_string(at->second) + ")");
      }
    }
    JsonObject object = value.object();
    Object o{id, std::nullopt, {}};
    const bool extension_type = object.get("type").string().starts_with('+');
    if (const std::optional<JsonValue> p = object.find("parents")) {
      const JsonArray list = p->array();
      if (!list.empty()) o.parent = list.at(0).string();
    }
    if (const std::optional<JsonValue> g = object.find("geometry")) {
      const JsonArray list = g->array();
      o.geometries.reserve(list.size());
      for (std::size_t i = 0; i < list.size(); ++i) {
        o.geometries.push_back(read_geometry(list.at(i), vertices, templates, false));
      }
    }
    for (const char* key : kOtherObjectKeys) object.has(key);
    if (extension_type) {
      for (const std::string& key : object.unknown_keys()) object.has(key);
    }
    finish_allowing_extension_keys(object);
    parents.emplace(id, o.parent);
    objects.push_back(std::move(o));
  }

  for (const Object& o : objects) {
    // The top of the parents chain, as far as this member knows it (a parent named but
    // absent is the top); a chain that loops stops where it would come round again.
    std::string group = o.id;
    for (std::size_t step = 0; step <= parents.size(); ++step) {
      const auto it = parents.find(group);
      if (it == parents.end() || !it->second) break;
      group = *it->second;
    }
    add_faces(o, group, vertices, templates, line);
  }
}

void CityObjectFaces::add_faces(const Object& object, const std::string& group,
                                const GeometryVertices& vertices,
                                const GeometryTemplates* templates, std::size_t line) {
  for (const Geometry& g : object.geometries) lods_seen_.insert(g.lod.text);
  const std::vector<std::size_t> chosen =
      chosen_geometries(object.geometries, templates, options_.lod);
  if (chosen.empty()) {
    if (!object.geometries.empty()) without_faces_.push_back(object.id);
    return;
  }
  any_chosen_ = true;
  std::size_t k = 0;
  auto add_ring = [&](const std::vector<std::size_t>& ring, const std::vector<glm::dvec3>& points,
                      const TemplatePlacement* placement) {
    hsr::Loop3 loop;
    loop.reserve(ring.size());
    for (const std::size_t index : ring) {
      const glm::dvec3 p =
          placement ? placement->linear * points[index] + placement->offset : points[index];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw InputError(file_, "",
                         "object '" + object.id + "' surface " + std::to_string(k) +
                             ": its template's transformationMatrix takes vertex " +
                             std::to_string(index) +
                             " of vertices-templates beyond the range of a double");
      }
      bounds_.add(p);
      loop.push_back(p);
    }
    return loop;
  };
  for (const std::size_t gi : chosen) {
    const Geometry& g = object.geometries[gi];
    const TemplatePlacement* placement = g.placement ? &*g.placement : nullptr;
    const Geometry& source = placement ? templates->templates[placement->template_index] : g;
    const std::vector<glm::dvec3>& points =
        placement ? templates->vertices.points : *vertices.points;
    const double rounding = placement ? placement->rounding : vertices.rounding;
    for (const Surface& surface : source.surfaces) {
      SourceFace face;
      face.id = object.id + "/" + std::to_string(k);
      face.polygon.outer = add_ring(surface.rings.front(), points, placement);
      for (std::size_t r = 1; r < surface.rings.size(); ++r) {
        face.polygon.holes.push_back(add_ring(surface.rings[r], points, placement));
      }
      face.origin = {"cityjson", object.id, group,
                     surface.semantic ? source.semantic_types[*surface.semantic] : ""};
      face.vertex_rounding = rounding;
      face.line = line;
      face.described = "object '" + object.id + "' surface " + std::to_string(k);
      faces_.push_back(std::move(face));
      ++k;
    }
  }
}

void CityObjectFaces::finish(std::vector<std::string>& warnings) const {
  if (options_.lod && !any_chosen_) {
    throw InputError(file_, "",
                     "no geometry has lod '" + *options_.lod + "' (" +
                         (lods_seen_.empty() ? std::string("the file has no geometry")
                                             : "the file's levels: " + list_of(lods_seen_)) +
                         ")");
  }
  if (without_faces_.empty()) return;
  std::string line = file_ + ": " + std::to_string(without_faces_.size()) +
                     (without_faces_.size() == 1 ? " city object has" : " city objects have") +
                     (options_.lod ? " no geometry of lod '" + *options_.lod + "'"
                                   : " no geometry with surfaces (only points or lines)") +
                     " and give" + (without_faces_.size() == 1 ? "s" : "") + " no faces: ";
  const std::size_t listed = std::min<std::size_t>(without_faces_.size(), 3);
  for (std::size_t i = 0; i < listed; ++i) line += (i ? ", " : "") + without_faces_[i];
  if (without_faces_.size() > listed) line += ", ...";
  warnings.push_back(one_line(line));
}

}  // namespace shadowgen::cityjson::detail
