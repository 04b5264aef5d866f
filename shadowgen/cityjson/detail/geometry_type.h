#pragma once

// CityJSON's geometry types (CityJSON 2.0 specification, "Geometry Objects") and the
// nesting of their "boundaries": a surface is an array of rings, the first the exterior,
// the others its holes, each an array of vertex indices; a MultiSurface or a
// CompositeSurface is an array of surfaces, a Solid an array of shells (the first the
// exterior, the others interior ones) each an array of surfaces, a MultiSolid or a
// CompositeSolid an array of Solids. MultiPoint and MultiLineString bound no surface; a
// GeometryInstance places a template (geometry_instance.h).

#include <optional>
#include <string>
#include <string_view>

namespace shadowgen::cityjson::detail {

enum class GeometryType {
  kMultiPoint,
  kMultiLineString,
  kMultiSurface,
  kCompositeSurface,
  kSolid,
  kMultiSolid,
  kCompositeSolid,
  kGeometryInstance,
};

// nullopt for a name CityJSON does not define.
std::optional<GeometryType> geometry_type(std::string_view name);
std::string_view geometry_type_name(GeometryType type);

// "MultiPoint, MultiLineString, ..., GeometryInstance", for messages.
std::string geometry_type_names();

// Whether the type's boundaries hold surfaces (a GeometryInstance: its template's do).
bool bounds_surfaces(GeometryType type);

// How many levels of arrays stand above the surfaces in the boundaries of a type that
// bounds surfaces: 0 for MultiSurface and CompositeSurface, 1 for Solid (shells), 2 for
// MultiSolid and CompositeSolid (solids, shells).
int levels_above_surfaces(GeometryType type);

// What the boundaries of a type that bounds surfaces hold, for messages: "shells of
// surfaces of rings of vertex indices".
std::string boundaries_shape(GeometryType type);

}  // namespace shadowgen::cityjson::detail
