#include "detail/placement_frame.h"

#include <algorithm>
#include <array>
#include <cctype>

#include "detail/object_fields.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::energyplus::detail {
namespace {

// GetGeometryParameters' corners, in the order that numbers them.
constexpr std::array<std::string_view, 4> kCorners = {"UPPERLEFTCORNER", "LOWERLEFTCORNER",
                                                      "LOWERRIGHTCORNER", "UPPERRIGHTCORNER"};

// A coordinate system choice: World or Absolute is true, Relative false, blank `blank`.
bool world_choice(const ObjectFields& rules, std::string_view key, bool blank) {
  const std::string value = name_key(rules.text(key));
  if (value.empty()) return blank;
  if (value == "WORLD" || value == "ABSOLUTE") return true;
  if (value == "RELATIVE") return false;
  rules.fail(key, "'" + rules.text(key) + "' is none of Relative, World, Absolute");
}

GeometryRules read_rules(const InputObject& object, const std::string& file) {
  const ObjectFields rules(object, file);
  GeometryRules out;
  const std::string corner = name_key(rules.required_text("starting_vertex_position"));
  const auto found = std::find(kCorners.begin(), kCorners.end(), corner);
  if (found == kCorners.end()) {
    rules.fail("starting_vertex_position",
               "'" + rules.text("starting_vertex_position") +
                   "' is none of UpperLeftCorner, LowerLeftCorner, LowerRightCorner, "
                   "UpperRightCorner");
  }
  out.starting_corner = static_cast<int>(found - kCorners.begin()) + 1;
  const std::string direction = name_key(rules.required_text("vertex_entry_direction"));
  if (direction == "CLOCKWISE" || direction == "CW") {
    out.clockwise = true;
  } else if (direction != "COUNTERCLOCKWISE" && direction != "CCW") {
    rules.fail("vertex_entry_direction", "'" + rules.text("vertex_entry_direction") +
                                             "' is neither Counterclockwise nor Clockwise");
  }
  (void)rules.required_text("coordinate_system");
  out.world = world_choice(rules, "coordinate_system", false);
  (void)world_choice(rules, "daylighting_reference_point_coordinate_system", false);
  out.rectangles_world = world_choice(rules, "rectangular_surface_coordinate_system", false);
  return out;
}

[[noreturn]] void second_object(const ObjectFields& object, const std::string& what) {
  object.fail("a second " + std::string(object.object().spec->name) + " object: " + what);
}

}  // namespace

std::string name_key(std::string_view name) {
  std::string key(name);
  std::transform(key.begin(), key.end(), key.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return key;
}

ModelFrame read_frame(const std::vector<InputObject>& objects, const std::string& file) {
  ModelFrame frame;
  bool have_rules = false;
  bool have_building = false;
  for (const InputObject& object : objects) {
    const ObjectFields fields(object, file);
    switch (object.spec->kind) {
      case ObjectKind::kGeometryRules:
        if (have_rules) second_object(fields, "EnergyPlus allows one");
        frame.placement.rules = read_rules(object, file);
        have_rules = true;
        break;
      case ObjectKind::kBuilding:
        if (have_building) second_object(fields, "EnergyPlus allows one");
        // The IDD's default north axis is 0.
        frame.placement.building_north_deg = fields.number("north_axis", 0.0);
        have_building = true;
        break;
      case ObjectKind::kZone: {
        ZoneFrame zone{object.name,
                       fields.number("direction_of_relative_north", 0.0),
                       {fields.number("x_origin", 0.0), fields.number("y_origin", 0.0),
                        fields.number("z_origin", 0.0)}};
        if (!frame.zones.emplace(name_key(object.name), zone).second) {
          fields.fail("a second zone of this name (names are compared ignoring case)");
        }
        break;
      }
      case ObjectKind::kAppendixGRotation:
        if (fields.number("building_rotation_for_appendix_g", 0.0) != 0.0) {
          fields.fail("building_rotation_for_appendix_g",
                      "an Appendix G rotation is not read; rotate the building with "
                      "Building's North Axis instead");
        }
        break;
      case ObjectKind::kGeometryTransform:
        fields.fail("GeometryTransform's stretching of surfaces is not read");
      default:
        break;
    }
  }
  if (!have_rules) {
    throw InputError(file, "",
                     "no GlobalGeometryRules object: EnergyPlus requires it to say how vertices "
                     "are entered");
  }
  return frame;
}

}  // namespace shadowgen::energyplus::detail
