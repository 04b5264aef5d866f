#include "detail/cityjson_header.h"

#include <string_view>

#include "detail/reference_system.h"

namespace shadowgen::cityjson::detail {
namespace {

bool readable_version(std::string_view version) {
  for (const std::string_view known : {"1.0", "1.1", "2.0"}) {
    if (version == known) return true;
    // A patch number (1.0.3) names the same minor version.
    if (version.starts_with(known) && version.size() > known.size() + 1 &&
        version[known.size()] == '.') {
      return true;
    }
  }
  return false;
}

}  // namespace

CityJsonHeader read_header(JsonObject& top) {
  const JsonValue type = top.get("type");
  if (const std::string name = type.string(); name != "CityJSON") {
    type.fail("expected \"CityJSON\", found '" + name + "'");
  }
  CityJsonHeader out;
  const JsonValue version = top.get("version");
  out.version = version.string();
  if (!readable_version(out.version)) {
    version.fail("CityJSON version '" + out.version +
                 "' is not one shadowgen reads (1.0, 1.1, 2.0)");
  }
  if (const std::optional<JsonValue> t = top.find("transform")) out.transform = read_transform(*t);
  if (const std::optional<JsonValue> m = top.find("metadata")) {
    if (const std::optional<JsonValue> r = m->object().find("referenceSystem")) {
      out.crs = crs_of_reference_system(*r);
    }
  }
  if (const std::optional<JsonValue> g = top.find("geometry-templates")) {
    out.templates = read_geometry_templates(*g);
  }
  top.has("extensions");
  top.has("appearance");
  return out;
}

}  // namespace shadowgen::cityjson::detail
