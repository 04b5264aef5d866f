#include "detail/geometry_type.h"

#include <array>
#include <utility>

namespace shadowgen::cityjson::detail {
namespace {

constexpr std::array<std::pair<std::string_view, GeometryType>, 8> kTypes = {{
    {"MultiPoint", GeometryType::kMultiPoint},
    {"MultiLineString", GeometryType::kMultiLineString},
    {"MultiSurface", GeometryType::kMultiSurface},
    {"CompositeSurface", GeometryType::kCompositeSurface},
    {"Solid", GeometryType::kSolid},
    {"MultiSolid", GeometryType::kMultiSolid},
    {"CompositeSolid", GeometryType::kCompositeSolid},
    {"GeometryInstance", GeometryType::kGeometryInstance},
}};

}  // namespace

std::optional<GeometryType> geometry_type(std::string_view name) {
  for (const auto& [type_name, type] : kTypes) {
    if (type_name == name) return type;
  }
  return std::nullopt;
}

std::string_view geometry_type_name(GeometryType type) {
  for (const auto& [type_name, t] : kTypes) {
    if (t == type) return type_name;
  }
  return "";
}

std::string geometry_type_names() {
  std::string names;
  for (const auto& [type_name, type] : kTypes) {
    if (!names.empty()) names += ", ";
    names += type_name;
  }
  return names;
}

bool bounds_surfaces(GeometryType type) {
  return type != GeometryType::kMultiPoint && type != GeometryType::kMultiLineString;
}

int levels_above_surfaces(GeometryType type) {
  switch (type) {
    case GeometryType::kSolid:
      return 1;
    case GeometryType::kMultiSolid:
    case GeometryType::kCompositeSolid:
      return 2;
    default:
      return 0;
  }
}

std::string boundaries_shape(GeometryType type) {
  switch (levels_above_surfaces(type)) {
    case 1:
      return "shells of surfaces of rings of vertex indices";
    case 2:
      return "solids of shells of surfaces of rings of vertex indices";
    default:
      return "surfaces of rings of vertex indices";
  }
}

}  // namespace shadowgen::cityjson::detail
