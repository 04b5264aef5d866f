#include "detail/object_classes.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace shadowgen::energyplus::detail {
namespace {

constexpr Version kSpaceNameSince{9, 6};
constexpr Version kShadingControlUntil{9, 0};

const FieldSpec kConstruction{"construction_name", "Construction Name"};
const FieldSpec kZoneName{"zone_name", "Zone Name"};
const FieldSpec kSpaceName{"space_name", "Space Name", kSpaceNameSince};
const FieldSpec kBoundary{"outside_boundary_condition", "Outside Boundary Condition"};
const FieldSpec kBoundaryObject{"outside_boundary_condition_object",
                                "Outside Boundary Condition Object"};
const FieldSpec kSunExposure{"sun_exposure", "Sun Exposure"};
const FieldSpec kWindExposure{"wind_exposure", "Wind Exposure"};
const FieldSpec kViewFactor{"view_factor_to_ground", "View Factor to Ground"};
const FieldSpec kVertexCount{"number_of_vertices", "Number of Vertices"};
const FieldSpec kSurfaceType{"surface_type", "Surface Type"};
const FieldSpec kBaseSurface{"building_surface_name", "Building Surface Name"};
const FieldSpec kShadingControl{
    "shading_control_name", "Shading Control Name", {0, 0}, kShadingControlUntil};
const FieldSpec kFrame{"frame_and_divider_name", "Frame and Divider Name"};
const FieldSpec kMultiplier{"multiplier", "Multiplier"};
const FieldSpec kTransmittance{"transmittance_schedule_name", "Transmittance Schedule Name"};
const FieldSpec kAzimuth{"azimuth_angle", "Azimuth Angle"};
const FieldSpec kTilt{"tilt_angle", "Tilt Angle"};
const FieldSpec kStartX{"starting_x_coordinate", "Starting X Coordinate"};
const FieldSpec kStartY{"starting_y_coordinate", "Starting Y Coordinate"};
const FieldSpec kStartZ{"starting_z_coordinate", "Starting Z Coordinate"};
const FieldSpec kLength{"length", "Length"};
const FieldSpec kHeight{"height", "Height"};
const FieldSpec kWidth{"width", "Width"};
const FieldSpec kOpeningName{"window_or_door_name", "Window or Door Name"};

// A class's description: its name, kind and fields; the rest set where it differs.
struct Described {
  std::string_view name;
  ObjectKind kind;
  bool named = true;
  std::vector<FieldSpec> fields;
  VertexFields vertices = VertexFields::kNone;
  SurfaceClass surface_class = SurfaceClass::kNone;
  std::string_view surface_type = {};
  double default_tilt = 0.0;
  std::string_view second_side = {};
};

std::vector<FieldSpec> joined(std::vector<FieldSpec> first, const std::vector<FieldSpec>& then) {
  for (const FieldSpec& field : then) first.push_back(field);
  return first;
}

std::vector<ClassSpec> make_classes() {
  std::vector<ClassSpec> classes;
  const auto add = [&](const Described& d) {
    ClassSpec spec;
    spec.name = d.name;
    spec.kind = d.kind;
    spec.named = d.named;
    spec.fields = d.fields;
    spec.vertices = d.vertices;
    spec.surface_class = d.surface_class;
    spec.surface_type = d.surface_type;
    spec.default_tilt = d.default_tilt;
    spec.second_side = d.second_side;
    classes.push_back(std::move(spec));
  };

  add({.name = "Version",
       .kind = ObjectKind::kVersion,
       .named = false,
       .fields = {{"version_identifier", "Version Identifier"}}});
  add({.name = "GlobalGeometryRules",
       .kind = ObjectKind::kGeometryRules,
       .named = false,
       .fields = {
           {"starting_vertex_position", "Starting Vertex Position"},
           {"vertex_entry_direction", "Vertex Entry Direction"},
           {"coordinate_system", "Coordinate System"},
           {"daylighting_reference_point_coordinate_system",
            "Daylighting Reference Point Coordinate System"},
           {"rectangular_surface_coordinate_system", "Rectangular Surface Coordinate System"}}});
  add({.name = "Building",
       .kind = ObjectKind::kBuilding,
       .fields = {
           {"north_axis", "North Axis"},
           {"terrain", "Terrain"},
           {"loads_convergence_tolerance_value", "Loads Convergence Tolerance Value"},
           {"temperature_convergence_tolerance_value", "Temperature Convergence Tolerance Value"},
           {"solar_distribution", "Solar Distribution"},
           {"maximum_number_of_warmup_days", "Maximum Number of Warmup Days"},
           {"minimum_number_of_warmup_days", "Minimum Number of Warmup Days"}}});
  add({.name = "Zone",
       .kind = ObjectKind::kZone,
       .fields = {{"direction_of_relative_north", "Direction of Relative North"},
                  {"x_origin", "X Origin"},
                  {"y_origin", "Y Origin"},
                  {"z_origin", "Z Origin"},
                  {"type", "Type"},
                  {"multiplier", "Multiplier"},
                  {"ceiling_height", "Ceiling Height"},
                  {"volume", "Volume"},
                  {"floor_area", "Floor Area"},
                  {"zone_inside_convection_algorithm", "Zone Inside Convection Algorithm"},
                  {"zone_outside_convection_algorithm", "Zone Outside Convection Algorithm"},
                  {"part_of_total_floor_area", "Part of Total Floor Area"}}});
  add({.name = "Site:Location",
       .kind = ObjectKind::kSiteLocation,
       .fields = {{"latitude", "Latitude"},
                  {"longitude", "Longitude"},
                  {"time_zone", "Time Zone"},
                  {"elevation", "Elevation"},
                  {"keep_site_location_information", "Keep Site Location Information"}}});
  add({.name = "Compliance:Building",
       .kind = ObjectKind::kAppendixGRotation,
       .named = false,
       .fields = {{"building_rotation_for_appendix_g", "Building Rotation for Appendix G"}}});
  add({.name = "GeometryTransform",
       .kind = ObjectKind::kGeometryTransform,
       .named = false,
       .fields = {{"plane_of_transform", "Plane of Transform"},
                  {"current_aspect_ratio", "Current Aspect Ratio"},
                  {"new_aspect_ratio", "New Aspect Ratio"}}});

  // Zone surfaces with vertices.
  const std::vector<FieldSpec> detailed = {kConstruction, kZoneName,       kSpaceName,
                                           kBoundary,     kBoundaryObject, kSunExposure,
                                           kWindExposure, kViewFactor,     kVertexCount};
  const std::vector<FieldSpec> building_surface = joined({kSurfaceType}, detailed);
  add({.name = "BuildingSurface:Detailed",
       .kind = ObjectKind::kDetailedSurface,
       .fields = building_surface,
       .vertices = VertexFields::kExtensible});
  add({.name = "Wall:Detailed",
       .kind = ObjectKind::kDetailedSurface,
       .fields = detailed,
       .vertices = VertexFields::kExtensible,
       .surface_class = SurfaceClass::kWall,
       .surface_type = "Wall"});
  add({.name = "RoofCeiling:Detailed",
       .kind = ObjectKind::kDetailedSurface,
       .fields = detailed,
       .vertices = VertexFields::kExtensible,
       .surface_class = SurfaceClass::kRoof,
       .surface_type = "Roof"});
  add({.name = "Floor:Detailed",
       .kind = ObjectKind::kDetailedSurface,
       .fields = detailed,
       .vertices = VertexFields::kExtensible,
       .surface_class = SurfaceClass::kFloor,
       .surface_type = "Floor"});
  add({.name = "FenestrationSurface:Detailed",
       .kind = ObjectKind::kDetailedOpening,
       .fields = {kSurfaceType, kConstruction, kBaseSurface, kBoundaryObject, kViewFactor,
                  kShadingControl, kFrame, kMultiplier, kVertexCount},
       .vertices = VertexFields::kFourAtMost,
       .surface_class = SurfaceClass::kOpening});
  add({.name = "Shading:Site:Detailed",
       .kind = ObjectKind::kDetailedShading,
       .fields = {kTransmittance, kVertexCount},
       .vertices = VertexFields::kExtensible,
       .surface_class = SurfaceClass::kSiteShading,
       .surface_type = "Shading:Site"});
  add({.name = "Shading:Building:Detailed",
       .kind = ObjectKind::kDetailedShading,
       .fields = {kTransmittance, kVertexCount},
       .vertices = VertexFields::kExtensible,
       .surface_class = SurfaceClass::kBuildingShading,
       .surface_type = "Shading:Building"});
  add({.name = "Shading:Zone:Detailed",
       .kind = ObjectKind::kZoneShading,
       .fields = {{"base_surface_name", "Base Surface Name"}, kTransmittance, kVertexCount},
       .vertices = VertexFields::kExtensible,
       .surface_class = SurfaceClass::kZoneShading,
       .surface_type = "Shading:Zone"});

  // Rectangular zone surfaces: a starting corner, an azimuth, a tilt, two sides.
  const auto rectangle = [&](std::string_view name, SurfaceClass surface_class,
                             std::string_view type, double tilt, bool interzone) {
    const FieldSpec& second = surface_class == SurfaceClass::kWall ? kHeight : kWidth;
    std::vector<FieldSpec> fields = {kConstruction, kZoneName, kSpaceName};
    if (interzone) fields.push_back(kBoundaryObject);
    fields =
        joined(std::move(fields), {kAzimuth, kTilt, kStartX, kStartY, kStartZ, kLength, second});
    add({.name = name,
         .kind = ObjectKind::kRectangularSurface,
         .fields = fields,
         .surface_class = surface_class,
         .surface_type = type,
         .default_tilt = tilt,
         .second_side = second.key});
  };
  rectangle("Wall:Exterior", SurfaceClass::kWall, "Wall", 90.0, false);
  rectangle("Wall:Adiabatic", SurfaceClass::kWall, "Wall", 90.0, false);
  rectangle("Wall:Underground", SurfaceClass::kWall, "Wall", 90.0, false);
  rectangle("Wall:Interzone", SurfaceClass::kWall, "Wall", 90.0, true);
  rectangle("Roof", SurfaceClass::kRoof, "Roof", 0.0, false);
  rectangle("Ceiling:Adiabatic", SurfaceClass::kRoof, "Ceiling", 0.0, false);
  rectangle("Ceiling:Interzone", SurfaceClass::kRoof, "Ceiling", 0.0, true);
  rectangle("Floor:GroundContact", SurfaceClass::kFloor, "Floor", 180.0, false);
  rectangle("Floor:Adiabatic", SurfaceClass::kFloor, "Floor", 180.0, false);
  rectangle("Floor:Interzone", SurfaceClass::kFloor, "Floor", 180.0, true);

  // Rectangular openings, placed on their base surface.
  const std::vector<FieldSpec> place = {kStartX, kStartZ, kLength, kHeight};
  const auto opening = [&](std::string_view name, std::string_view type,
                           std::vector<FieldSpec> fields) {
    add({.name = name,
         .kind = ObjectKind::kRectangularOpening,
         .fields = joined(std::move(fields), place),
         .surface_class = SurfaceClass::kOpening,
         .surface_type = type});
  };
  opening("Window", "Window", {kConstruction, kBaseSurface, kShadingControl, kFrame, kMultiplier});
  opening("Door", "Door", {kConstruction, kBaseSurface, kMultiplier});
  opening("GlazedDoor", "GlassDoor",
          {kConstruction, kBaseSurface, kShadingControl, kFrame, kMultiplier});
  opening("Window:Interzone", "Window",
          {kConstruction, kBaseSurface, kBoundaryObject, kMultiplier});
  opening("Door:Interzone", "Door", {kConstruction, kBaseSurface, kBoundaryObject, kMultiplier});
  opening("GlazedDoor:Interzone", "GlassDoor",
          {kConstruction, kBaseSurface, kBoundaryObject, kMultiplier});

  const std::vector<FieldSpec> shading = {kAzimuth, kTilt,   kStartX, kStartY,
                                          kStartZ,  kLength, kHeight};
  add({.name = "Shading:Site",
       .kind = ObjectKind::kRectangularShading,
       .fields = shading,
       .surface_class = SurfaceClass::kSiteShading,
       .surface_type = "Shading:Site"});
  add({.name = "Shading:Building",
       .kind = ObjectKind::kRectangularShading,
       .fields = shading,
       .surface_class = SurfaceClass::kBuildingShading,
       .surface_type = "Shading:Building"});

  const auto overhang = [&](std::string_view name, FieldSpec depth) {
    add({.name = name,
         .kind = ObjectKind::kOverhang,
         .fields = {kOpeningName,
                    {"height_above_window_or_door", "Height above Window or Door"},
                    {"tilt_angle_from_window_door", "Tilt Angle from Window/Door"},
                    {"left_extension_from_window_door_width",
                     "Left extension from Window/Door Width"},
                    {"right_extension_from_window_door_width",
                     "Right extension from Window/Door Width"},
                    depth},
         .surface_class = SurfaceClass::kZoneShading,
         .surface_type = "Shading:Zone"});
  };
  overhang("Shading:Overhang", {"depth", "Depth"});
  overhang("Shading:Overhang:Projection",
           {"depth_as_fraction_of_window_door_height", "Depth as Fraction of Window/Door Height"});

  const auto fin = [&](std::string_view name, FieldSpec left_depth, FieldSpec right_depth) {
    add({.name = name,
         .kind = ObjectKind::kFin,
         .fields = {kOpeningName,
                    {"left_extension_from_window_door", "Left Extension from Window/Door"},
                    {"left_distance_above_top_of_window", "Left Distance Above Top of Window"},
                    {"left_distance_below_bottom_of_window",
                     "Left Distance Below Bottom of Window"},
                    {"left_tilt_angle_from_window_door", "Left Tilt Angle from Window/Door"},
                    left_depth,
                    {"right_extension_from_window_door", "Right Extension from Window/Door"},
                    {"right_distance_above_top_of_window", "Right Distance Above Top of Window"},
                    {"right_distance_below_bottom_of_window",
                     "Right Distance Below Bottom of Window"},
                    {"right_tilt_angle_from_window_door", "Right Tilt Angle from Window/Door"},
                    right_depth},
         .surface_class = SurfaceClass::kZoneShading,
         .surface_type = "Shading:Zone"});
  };
  fin("Shading:Fin", {"left_depth", "Left Depth"}, {"right_depth", "Right Depth"});
  fin("Shading:Fin:Projection",
      {"left_depth_as_fraction_of_window_door_width",
       "Left Depth as Fraction of Window/Door Width"},
      {"right_depth_as_fraction_of_window_door_width",
       "Right Depth as Fraction of Window/Door Width"});
  return classes;
}

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

const ClassSpec* find_class(std::string_view name) {
  static const std::vector<ClassSpec> classes = make_classes();
  const std::string wanted = lower(name);
  for (const ClassSpec& spec : classes) {
    if (lower(spec.name) == wanted) return &spec;
  }
  return nullptr;
}

std::vector<const FieldSpec*> fields_in(const ClassSpec& spec, Version version) {
  std::vector<const FieldSpec*> fields;
  for (const FieldSpec& field : spec.fields) {
    if (field.since <= version && version < field.until) fields.push_back(&field);
  }
  return fields;
}

}  // namespace shadowgen::energyplus::detail
