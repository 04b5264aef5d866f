#include "detail/model_builder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "detail/attached_shading.h"
#include "detail/object_fields.h"
#include "detail/placement_frame.h"
#include "detail/site_location.h"
#include "hsr/polygon3.h"

namespace shadowgen::energyplus::detail {
namespace {

constexpr std::string_view kFormat = "energyplus";
// FenestrationSurface:Detailed holds at most 4 vertices (the IDD's \maximum 4).
constexpr std::size_t kMostOpeningVertices = 4;
constexpr std::size_t kMostVertices = static_cast<std::size_t>(-1);
// How far from its base's plane an opening computed on it may lie by rounding alone,
// relative to the largest coordinate: a few operations' rounding (2^-52 each) on the
// corner, the sines and the sides, with the plane's own fit; 64 ε = 1.4e-14.
constexpr double kPlaneRounding = 64.0 * std::numeric_limits<double>::epsilon();

// A surface made of an object, before its holes are cut.
struct Surface {
  std::string id;  // the EnergyPlus surface Name: the object's, a fin's with " Left"/" Right"
  PlacedSurface placed;
  const ZoneFrame* zone = nullptr;
  std::string semantic;
  SurfaceClass surface_class = SurfaceClass::kNone;
  double rounding = 0.0;
  std::vector<hsr::Loop3> holes;
  std::string described;
  // An opening's base surface: the object that made it (a base surface's only surface).
  std::size_t base_object = 0;
};

// Surface Type choices: the IDD's keys, as FaceOrigin writes them, with the class each
// gives (a ceiling is a roof to GetHTSurfaceData).
struct TypeChoice {
  std::string_view key;
  std::string_view type;
  SurfaceClass surface_class;
};
constexpr std::array<TypeChoice, 4> kBaseTypes = {{{"FLOOR", "Floor", SurfaceClass::kFloor},
                                                   {"WALL", "Wall", SurfaceClass::kWall},
                                                   {"CEILING", "Ceiling", SurfaceClass::kRoof},
                                                   {"ROOF", "Roof", SurfaceClass::kRoof}}};
constexpr std::array<TypeChoice, 5> kOpeningTypes = {
    {{"WINDOW", "Window", SurfaceClass::kOpening},
     {"DOOR", "Door", SurfaceClass::kOpening},
     {"GLASSDOOR", "GlassDoor", SurfaceClass::kOpening},
     {"TUBULARDAYLIGHTDOME", "TubularDaylightDome", SurfaceClass::kOpening},
     {"TUBULARDAYLIGHTDIFFUSER", "TubularDaylightDiffuser", SurfaceClass::kOpening}}};

template <std::size_t N>
const TypeChoice& surface_type(const ObjectFields& fields,
                               const std::array<TypeChoice, N>& choices) {
  const std::string given = fields.required_text("surface_type");
  for (const TypeChoice& choice : choices) {
    if (name_key(given) == choice.key) return choice;
  }
  std::string known;
  for (const TypeChoice& choice : choices) {
    known += (known.empty() ? "" : ", ") + std::string(choice.type);
  }
  fields.fail("surface_type", "'" + given + "' is none of " + known);
}

class ModelBuilder {
 public:
  ModelBuilder(const std::vector<InputObject>& objects, const std::string& file)
      : objects_(objects), file_(file), frame_(read_frame(objects, file)) {
    model_.site = read_site(objects, file);
    made_.resize(objects.size());
  }

  SourceModel run() {
    // EnergyPlus reads base surfaces, then openings, then the shading attached to them,
    // whatever their order in the file.
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      const ObjectKind kind = objects_[i].spec->kind;
      if (kind == ObjectKind::kDetailedSurface || kind == ObjectKind::kRectangularSurface ||
          kind == ObjectKind::kDetailedShading || kind == ObjectKind::kRectangularShading) {
        make(i);
      }
    }
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      const ObjectKind kind = objects_[i].spec->kind;
      if (kind == ObjectKind::kDetailedOpening || kind == ObjectKind::kRectangularOpening) make(i);
    }
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      const ObjectKind kind = objects_[i].spec->kind;
      if (kind == ObjectKind::kZoneShading || kind == ObjectKind::kOverhang ||
          kind == ObjectKind::kFin) {
        make(i);
      }
    }
    emit();
    return std::move(model_);
  }

 private:
  void make(std::size_t index) {
    const InputObject& object = objects_[index];
    const ObjectFields fields(object, file_);
    if (name_key(object.name).empty()) fields.fail("a surface without a Name");
    switch (object.spec->kind) {
      case ObjectKind::kDetailedSurface:
        add(index, detailed_surface(fields));
        break;
      case ObjectKind::kRectangularSurface:
        add(index, rectangular_surface(fields));
        break;
      case ObjectKind::kDetailedShading:
        add(index, detached_shading(fields, true));
        break;
      case ObjectKind::kRectangularShading:
        add(index, detached_shading(fields, false));
        break;
      case ObjectKind::kDetailedOpening:
      case ObjectKind::kRectangularOpening:
        add(index, opening(fields));
        break;
      case ObjectKind::kZoneShading:
        add(index, zone_shading(fields));
        break;
      case ObjectKind::kOverhang:
      case ObjectKind::kFin:
        attached_shading(index, fields);
        break;
      default:
        break;
    }
  }

  Surface start(const ObjectFields& fields, const ClassSpec& spec) const {
    Surface s;
    s.id = fields.name();
    s.described = fields.described();
    s.semantic = std::string(spec.surface_type);
    s.surface_class = spec.surface_class;
    return s;
  }

  const ZoneFrame* zone_of(const ObjectFields& fields) const {
    const std::string name = fields.required_text("zone_name");
    const auto found = frame_.zones.find(name_key(name));
    if (found == frame_.zones.end()) fields.fail("zone_name", "no Zone is named '" + name + "'");
    return &found->second;
  }

  Surface detailed_surface(const ObjectFields& fields) const {
    const ClassSpec& spec = *fields.object().spec;
    Surface s = start(fields, spec);
    if (spec.surface_type.empty()) {
      const TypeChoice& type = surface_type(fields, kBaseTypes);
      s.semantic = std::string(type.type);
      s.surface_class = type.surface_class;
    }
    s.zone = zone_of(fields);
    s.placed =
        place_vertices(fields.vertices(kMostVertices), frame_.placement, s.zone, s.surface_class);
    s.rounding = fields.vertex_rounding();
    return s;
  }

  Surface rectangular_surface(const ObjectFields& fields) const {
    const ClassSpec& spec = *fields.object().spec;
    Surface s = start(fields, spec);
    s.zone = zone_of(fields);
    s.placed = place_rectangle(frame_.placement, s.zone, s.surface_class,
                               fields.number("azimuth_angle", 0.0),
                               fields.number("tilt_angle", spec.default_tilt), start_corner(fields),
                               fields.number("length", 0.0), fields.number(spec.second_side, 0.0));
    return s;
  }

  static glm::dvec3 start_corner(const ObjectFields& fields) {
    return {fields.number("starting_x_coordinate", 0.0),
            fields.number("starting_y_coordinate", 0.0),
            fields.number("starting_z_coordinate", 0.0)};
  }

  Surface detached_shading(const ObjectFields& fields, bool detailed) const {
    const ClassSpec& spec = *fields.object().spec;
    Surface s = start(fields, spec);
    if (detailed) {
      s.placed = place_vertices(fields.vertices(kMostVertices), frame_.placement, nullptr,
                                s.surface_class);
      s.rounding = fields.vertex_rounding();
    } else {
      // The IDD's default tilt of Shading:Site and Shading:Building is 90 (upright).
      s.placed = place_rectangle(frame_.placement, nullptr, s.surface_class,
                                 fields.number("azimuth_angle", 0.0),
                                 fields.number("tilt_angle", 90.0), start_corner(fields),
                                 fields.number("length", 0.0), fields.number("height", 0.0));
    }
    return s;
  }

  // The surface `key` names: an opening, or a base surface; `what` says which for messages.
  // Its object and the surface.
  std::pair<std::size_t, const Surface*> named_surface(const ObjectFields& fields,
                                                       std::string_view key, bool openings,
                                                       std::string_view what) const {
    const std::string name = fields.required_text(key);
    const auto found = surfaces_.find(name_key(name));
    if (found != surfaces_.end()) {
      const Surface& s = made_[found->second.first][found->second.second];
      const bool opening = s.surface_class == SurfaceClass::kOpening;
      const bool base = s.surface_class == SurfaceClass::kWall ||
                        s.surface_class == SurfaceClass::kRoof ||
                        s.surface_class == SurfaceClass::kFloor;
      if ((openings && opening) || (!openings && base)) return {found->second.first, &s};
    }
    fields.fail(key, "no " + std::string(what) + " is named '" + name + "'");
  }

  Surface opening(const ObjectFields& fields) {
    const ClassSpec& spec = *fields.object().spec;
    Surface s = start(fields, spec);
    if (spec.surface_type.empty())
      s.semantic = std::string(surface_type(fields, kOpeningTypes).type);
    const auto [base_index, base] =
        named_surface(fields, "building_surface_name", false, "base surface (wall, roof, floor)");
    s.zone = base->zone;
    s.base_object = base_index;
    if (spec.kind == ObjectKind::kDetailedOpening) {
      s.placed = place_vertices(fields.vertices(kMostOpeningVertices), frame_.placement, s.zone,
                                s.surface_class);
      s.rounding = fields.vertex_rounding();
    } else {
      // GetRectSubSurfaces: the opening faces as its base does.
      s.placed = place_on_base(base->placed, base->placed.azimuth_deg, base->placed.tilt_deg,
                               fields.number("starting_x_coordinate", 0.0),
                               fields.number("starting_z_coordinate", 0.0),
                               fields.number("length", 0.0), fields.number("height", 0.0));
    }
    cut_hole(base_index, s.placed.vertices);
    return s;
  }

  // The opening's vertices, taken along the base surface's normal into its plane, as a
  // hole of the base surface. An opening already in that plane to within the rounding of
  // computing it there is kept as it is: a door placed on its wall from the wall's own
  // corner has its sill exactly on the wall's lower edge, and moving it by a rounding
  // error along a normal that is itself rounded would take it off that edge.
  void cut_hole(std::size_t base_index, const std::vector<glm::dvec3>& vertices) {
    Surface& base = made_[base_index][0];
    const hsr::Plane3 plane = hsr::plane_of(hsr::Polygon3{base.placed.vertices, {}});
    double extent = 0.0;
    for (const glm::dvec3& p : base.placed.vertices) {
      extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    bool in_plane = true;
    for (const glm::dvec3& p : vertices) {
      in_plane = in_plane && std::abs(plane.signed_distance(p)) <= kPlaneRounding * extent;
    }
    hsr::Loop3 hole;
    for (const glm::dvec3& p : vertices) {
      hole.push_back(in_plane ? p : p - plane.normal * plane.signed_distance(p));
    }
    base.holes.push_back(std::move(hole));
  }

  Surface zone_shading(const ObjectFields& fields) const {
    const ClassSpec& spec = *fields.object().spec;
    Surface s = start(fields, spec);
    const std::string name = fields.required_text("base_surface_name");
    const auto found = surfaces_.find(name_key(name));
    if (found == surfaces_.end() ||
        made_[found->second.first][found->second.second].zone == nullptr) {
      fields.fail("base_surface_name", "no zone surface is named '" + name + "'");
    }
    s.zone = made_[found->second.first][found->second.second].zone;
    s.placed =
        place_vertices(fields.vertices(kMostVertices), frame_.placement, s.zone, s.surface_class);
    s.rounding = fields.vertex_rounding();
    return s;
  }

  void attached_shading(std::size_t index, const ObjectFields& fields) {
    const ClassSpec& spec = *fields.object().spec;
    const Surface* opening =
        named_surface(fields, "window_or_door_name", true, "window or door").second;
    const Surface& base = made_[opening->base_object][0];
    if (spec.kind == ObjectKind::kOverhang) {
      std::optional<PlacedSurface> placed = place_overhang(fields, opening->placed, base.placed);
      if (!placed) return not_entered(fields, "");
      Surface s = start(fields, spec);
      s.zone = opening->zone;
      s.placed = std::move(*placed);
      add(index, std::move(s));
      return;
    }
    std::array<std::optional<PlacedSurface>, 2> fins =
        place_fins(fields, opening->placed, base.placed);
    for (int side = 0; side < 2; ++side) {
      const std::string which = side == 0 ? "Left" : "Right";
      if (!fins[side]) {
        not_entered(fields, "its " + which + " fin: ");
        continue;
      }
      Surface s = start(fields, spec);
      s.id = fields.name() + " " + which;
      s.described = fields.described() + " (its fin '" + s.id + "')";
      s.zone = opening->zone;
      s.placed = std::move(*fins[side]);
      add(index, std::move(s));
    }
  }

  void not_entered(const ObjectFields& fields, const std::string& part) {
    std::string line = file_ + ": ";
    if (fields.object().line > 0) line += "line " + std::to_string(fields.object().line) + ": ";
    model_.warnings.push_back(line + fields.described() + ": " + part +
                              "its length times its depth is not positive; EnergyPlus enters "
                              "no surface for it, and neither does this reader");
  }

  void add(std::size_t index, Surface s) {
    const std::string key = name_key(s.id);
    const auto [it, inserted] = surfaces_.emplace(key, std::make_pair(index, made_[index].size()));
    if (!inserted) {
      const InputObject& first = objects_[it->second.first];
      std::string where = made_[it->second.first][it->second.second].described;
      if (first.line > 0) where += " on line " + std::to_string(first.line);
      ObjectFields(objects_[index], file_)
          .fail("the surface '" + s.id + "' has the Name of " + where +
                "; EnergyPlus's surface Names are unique, compared ignoring case");
    }
    made_[index].push_back(std::move(s));
  }

  void emit() {
    std::vector<std::string> dropped;
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      for (Surface& s : made_[i]) {
        if (s.placed.dropped_vertices > 0) dropped.push_back(s.id);
        SourceFace face;
        face.id = s.id;
        face.polygon.outer = std::move(s.placed.vertices);
        face.polygon.holes = std::move(s.holes);
        face.origin =
            FaceOrigin{std::string(kFormat), s.id, s.zone ? s.zone->name : "", s.semantic};
        face.vertex_rounding = s.rounding;
        face.line = objects_[i].line;
        face.described = std::move(s.described);
        model_.faces.push_back(std::move(face));
      }
    }
    if (!dropped.empty()) {
      std::string names;
      for (std::size_t k = 0; k < dropped.size() && k < 3; ++k) {
        names += (k == 0 ? "'" : ", '") + dropped[k] + "'";
      }
      if (dropped.size() > 3) names += ", ...";
      model_.warnings.push_back(
          file_ + ": " + std::to_string(dropped.size()) +
          (dropped.size() == 1 ? " surface has" : " surfaces have") +
          " a vertex within 0.01 m of the one before it, dropped as EnergyPlus drops it: " + names);
    }
  }

  const std::vector<InputObject>& objects_;
  const std::string& file_;
  ModelFrame frame_;
  SourceModel model_;
  std::vector<std::vector<Surface>> made_;  // by object
  // Every surface made so far by name_key: its object and its place among the object's.
  std::map<std::string, std::pair<std::size_t, std::size_t>> surfaces_;
};

}  // namespace

SourceModel build_model(const std::vector<InputObject>& objects, const std::string& file) {
  return ModelBuilder(objects, file).run();
}

}  // namespace shadowgen::energyplus::detail
