#pragma once

// The EnergyPlus input objects this room reads, with their fields in IDF order as the
// Input Data Dictionary (Energy+.idd) of each version from 8.9 on lists them, and the
// names epJSON gives the same fields (docs/energyplus.md, "What is read"). Two changes of
// field order matter here: 9.0 removed `Shading Control Name` from
// FenestrationSurface:Detailed, Window and GlazedDoor (Rules8-9-0-to-9-0-0), and 9.6
// inserted `Space Name` after `Zone Name` in every zone surface object (the detailed and
// the rectangular ones); FieldSpec::since and until say so. Every other object of a file
// is skipped.

#include <string_view>
#include <vector>

namespace shadowgen::energyplus::detail {

// An EnergyPlus version as its Version object writes it ("9.6", "24.1.0"): major.minor.
struct Version {
  int major = 0;
  int minor = 0;
  auto operator<=>(const Version&) const = default;
};

enum class ObjectKind {
  kVersion,
  kGeometryRules,       // GlobalGeometryRules
  kBuilding,            // Building: the north axis
  kZone,                // Zone: origin and direction of relative north
  kSiteLocation,        // Site:Location
  kAppendixGRotation,   // Compliance:Building (refused when it rotates)
  kGeometryTransform,   // GeometryTransform (refused)
  kDetailedSurface,     // BuildingSurface:Detailed, Wall:Detailed, RoofCeiling:Detailed, ...
  kDetailedOpening,     // FenestrationSurface:Detailed
  kDetailedShading,     // Shading:Site:Detailed, Shading:Building:Detailed
  kZoneShading,         // Shading:Zone:Detailed
  kRectangularSurface,  // Wall:Exterior ... Floor:Interzone
  kRectangularOpening,  // Window, Door, GlazedDoor and their :Interzone forms
  kRectangularShading,  // Shading:Site, Shading:Building
  kOverhang,            // Shading:Overhang, Shading:Overhang:Projection
  kFin,                 // Shading:Fin, Shading:Fin:Projection
};

// How an object writes its vertices after its `Number of Vertices` field: none, an
// extensible list (epJSON: a "vertices" array of {vertex_x_coordinate, ...}), or at most
// four fixed ones (FenestrationSurface:Detailed; epJSON: vertex_1_x_coordinate, ...).
enum class VertexFields { kNone, kExtensible, kFourAtMost };

struct FieldSpec {
  std::string_view key;       // epJSON's name of the field
  std::string_view idf_name;  // the IDD's \field name, for messages
  Version since{0, 0};        // the first version with the field
  Version until{99, 0};       // the first version without it
};

// What EnergyPlus makes of a surface: its class (SurfaceGeometry.cc's SurfaceClass, which
// decides how vertices are placed) and the type reports give it (FaceOrigin::semantic).
enum class SurfaceClass {
  kNone,  // not a surface
  kWall,
  kRoof,             // roofs and ceilings: EnergyPlus turns an upside-down one over
  kFloor,            // turned over when upside down, too
  kOpening,          // windows, doors, glass doors, tubular daylighting devices
  kSiteShading,      // Detached_F: never rotated
  kBuildingShading,  // Detached_B: rotated with the building's north axis only
  kZoneShading,      // attached to a zone surface
};

struct ClassSpec {
  std::string_view name;  // as the IDD writes it
  ObjectKind kind;
  bool named = true;  // the first field is the Name (not for unique objects like Version)
  std::vector<FieldSpec> fields;  // after the Name, in IDF order
  VertexFields vertices = VertexFields::kNone;
  SurfaceClass surface_class = SurfaceClass::kNone;
  // The surface type reports give the object's faces, where the class fixes it;
  // empty where a field says it (BuildingSurface:Detailed's and
  // FenestrationSurface:Detailed's Surface Type).
  std::string_view surface_type;
  // Rectangular surfaces: the IDD's default tilt (90 for walls, 0 for roofs and
  // ceilings, 180 for floors) and the key of the second side (height or width).
  double default_tilt = 0.0;
  std::string_view second_side;
};

// The class named `name`, compared as EnergyPlus compares them (case-insensitively);
// nullptr for any other object.
const ClassSpec* find_class(std::string_view name);

// The fields `spec` has in `version`, in IDF order.
std::vector<const FieldSpec*> fields_in(const ClassSpec& spec, Version version);

}  // namespace shadowgen::energyplus::detail
