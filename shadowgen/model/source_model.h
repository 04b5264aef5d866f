#pragma once

// A model file of another tool read into scene terms (docs/scene-format.md, "Model
// files"): what each source-format room (shadowgen/energyplus, shadowgen/cityjson,
// shadowgen/gltf) gives the scene reader, which builds its faces exactly as it builds a
// scene's own polygons (the checks, the planarity rule, the face ids "<entry id>/<id>").
//
//   SourceModel model = energyplus::read_energyplus(path, {.strict = ...});
//   for (SourceFace& f : model.faces) ... "<entry id>/" + f.id ...
//
// Coordinates are the scene's: +z up, in the source's own unit (metres for EnergyPlus and
// CityJSON), placed as the source format places them (EnergyPlus's zone origins and north
// axes, CityJSON's transform, glTF's node hierarchy and its +y up turned to +z up). The
// scene entry's `transform` applies after that.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "hsr/polygon3.h"

namespace shadowgen {

// Where a face comes from in its source, kept with the face through every output
// (reports, the database, exports, schedules). Empty strings where the source has
// nothing to say; all empty for a scene's own polygons and for OBJ, STL, OFF and PLY.
struct FaceOrigin {
  // The source format: "energyplus", "cityjson", "gltf"; empty for a scene's own faces.
  std::string format;
  // The name the source gives the surface or object the face is, as written:
  // EnergyPlus's surface Name (what its Schedule:File:Shading columns match, in upper
  // case), the CityJSON city object holding the geometry, the glTF node's name (or its
  // index, as text, when it has none).
  std::string object;
  // The larger whole it belongs to: EnergyPlus's zone (empty for site and building
  // shading), the CityJSON parent object of a BuildingPart or other child (the object
  // itself when it has no parent), the glTF mesh's name.
  std::string group;
  // What kind of surface the source says it is: a CityJSON semantic surface type
  // ("RoofSurface", "WallSurface", "GroundSurface", ...), EnergyPlus's surface type
  // ("Wall", "Roof", "Floor", "Ceiling", "Window", "Door", "GlassDoor", "Shading:Site",
  // "Shading:Building", "Shading:Zone"); empty where the source does not say.
  std::string semantic;

  bool empty() const { return format.empty(); }
  bool operator==(const FaceOrigin&) const = default;
};

// One face of a source model.
struct SourceFace {
  // The face's id inside its scene entry: the scene's face id is "<entry id>/<id>".
  // Unique within the model: each room's rules make ids unique, and it refuses, naming
  // both, a model whose faces those rules would give one id (the scene reader does not
  // look again: a model may hold millions of faces).
  std::string id;
  // The face's loops in scene coordinates as the source places them; holes as the
  // source (or its openings) gives them. The scene reader validates and orients them.
  hsr::Polygon3 polygon;
  FaceOrigin origin;
  // How far the source's stated precision may have moved each vertex from where it was
  // meant to be, as a distance (CityJSON's transform scale, the decimals an IDF writes,
  // glTF's float32): the scene reader counts a face planar when every vertex lies within
  // twice this (or the relative tolerance kPlanarityTolerance) of its best-fit plane.
  // 0 where the source is exact.
  double vertex_rounding = 0.0;
  // For messages: the line of a text file the face is written on (0 when none), and
  // what the source calls it ("BuildingSurface:Detailed 'Zn001:Wall001'",
  // "object 'NL.IMBAG.Pand.0363' surface 4", "node 'roof' triangle 12").
  std::size_t line = 0;
  std::string described;
};

// What the source says of where it stands on the Earth: each value where it knows it.
// The scene's own `site` keys win over these (docs/scene-format.md, "The site").
struct SourceSite {
  std::optional<double> latitude_deg;
  std::optional<double> longitude_deg;
  std::optional<double> elevation_m;
  std::optional<double> utc_offset_h;
  std::optional<double> north_axis_deg;
  // Where these come from, for messages and docs: "Site:Location 'Chicago'",
  // "EPSG:28992 through PROJ at (155000, 463000)".
  std::string from;

  bool empty() const {
    return !latitude_deg && !longitude_deg && !elevation_m && !utc_offset_h && !north_axis_deg;
  }
};

struct SourceModel {
  std::vector<SourceFace> faces;  // in the order the format's rules give
  SourceSite site;
  // Lines the source's reader warns with ("file: what"), in order; the scene reader
  // passes them on.
  std::vector<std::string> warnings;
};

// How a source file is to be read, from the scene's entry and the command line.
struct SourceOptions {
  bool strict = false;  // unknown keys (JSON formats) are errors, not warnings
  // CityJSON: the level of detail to take (as the file writes it: "2.2", "1"); nullopt
  // for each object's highest.
  std::optional<std::string> lod;
};

}  // namespace shadowgen
