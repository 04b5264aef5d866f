#pragma once

// Surfaces placed exactly as EnergyPlus places them, step for step as its
// src/EnergyPlus/SurfaceGeometry.cc does (GetVertices, MakeRectangularVertices,
// MakeRelativeRectangularVertices) and src/EnergyPlus/Vectors.cc
// (CreateNewellSurfaceNormalVector, DetermineAzimuthAndTilt): the same vertices in the
// same order, the same azimuths and tilts, so that a window placed on a wall, or an
// overhang above it, lands where EnergyPlus puts it (docs/energyplus.md, "Placement").
//
// Coordinates out are EnergyPlus's world coordinates: metres, +x east, +y true north, +z
// up, each surface's vertices counter-clockwise seen from its outside (its outward
// normal by the right-hand rule). Angles are degrees, azimuths clockwise from north.

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "detail/object_classes.h"

namespace shadowgen::energyplus::detail {

// GlobalGeometryRules.
struct GeometryRules {
  // Starting Vertex Position, as EnergyPlus numbers it: 1 UpperLeftCorner, 2
  // LowerLeftCorner, 3 LowerRightCorner, 4 UpperRightCorner.
  int starting_corner = 1;
  bool clockwise = false;         // Vertex Entry Direction
  bool world = false;             // Coordinate System World (or Absolute), not Relative
  bool rectangles_world = false;  // Rectangular Surface Coordinate System, the same
};

// A Zone's Direction of Relative North and origin.
struct ZoneFrame {
  std::string name;
  double relative_north_deg = 0.0;
  glm::dvec3 origin{0.0};
};

struct PlacementFrame {
  GeometryRules rules;
  double building_north_deg = 0.0;  // Building's North Axis
};

// A surface as EnergyPlus holds it once its input is read.
struct PlacedSurface {
  std::vector<glm::dvec3> vertices;  // EnergyPlus's order: vertex 2 a rectangle's lower left
  double azimuth_deg = 0.0;          // Surface.Azimuth and Tilt (DetermineAzimuthAndTilt)
  double tilt_deg = 0.0;
  // Surface.SinAzim, CosAzim, SinTilt, CosTilt: of the entered azimuth and tilt for a
  // rectangular surface, of the computed ones for a surface entered by its vertices.
  double sin_azimuth = 0.0, cos_azimuth = 1.0, sin_tilt = 0.0, cos_tilt = 1.0;
  double width = 0.0, height = 0.0;  // Surface.Width and Height
  // How many vertices GetVertices dropped for lying within 0.01 m of the one before.
  std::size_t dropped_vertices = 0;
};

// GetVertices: the entered vertices of a surface of `surface_class`, in `zone` (nullptr
// for site and building shading): turned counter-clockwise and to start at the upper left
// corner as GlobalGeometryRules says they are entered, placed in the zone (relative
// coordinates) or taken as they are (world), vertices within 0.01 m of the one before
// dropped while more than 3 remain, a roof facing down or a floor facing up turned over.
PlacedSurface place_vertices(std::vector<glm::dvec3> vertices, const PlacementFrame& frame,
                             const ZoneFrame* zone, SurfaceClass surface_class);

// MakeRectangularVertices: a rectangle `length` by `height` from its lower left corner
// `start`, facing `azimuth_deg` (as entered: the zone's and building's north axes are added
// here as EnergyPlus adds them), tilted `tilt_deg` from the horizontal.
PlacedSurface place_rectangle(const PlacementFrame& frame, const ZoneFrame* zone,
                              SurfaceClass surface_class, double azimuth_deg, double tilt_deg,
                              const glm::dvec3& start, double length, double height);

// MakeRelativeRectangularVertices: a rectangle `length` by `height`, facing `azimuth_deg`
// and tilted `tilt_deg`, its lower left corner `x` along and `z` up `base` from the base's
// vertex 2 (the base's own azimuth and tilt give "along" and "up").
PlacedSurface place_on_base(const PlacedSurface& base, double azimuth_deg, double tilt_deg,
                            double x, double z, double length, double height);

}  // namespace shadowgen::energyplus::detail
