#include "detail/reference_system.h"

#include <algorithm>
#include <string_view>
#include <vector>

namespace shadowgen::cityjson::detail {
namespace {

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

bool is_name(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.';
  });
}

}  // namespace

std::string crs_of_reference_system(const JsonValue& value) {
  const std::string text = value.string();
  std::string_view rest;
  std::vector<std::string_view> parts;
  for (const std::string_view prefix :
       {"https://www.opengis.net/def/crs/", "http://www.opengis.net/def/crs/"}) {
    if (std::string_view(text).starts_with(prefix)) {
      rest = std::string_view(text).substr(prefix.size());
      parts = split(rest, '/');
    }
  }
  constexpr std::string_view kUrn = "urn:ogc:def:crs:";
  if (parts.empty() && std::string_view(text).starts_with(kUrn)) {
    parts = split(std::string_view(text).substr(kUrn.size()), ':');
  }
  // {authority}, {version} (any, possibly empty), {code}
  if (parts.size() == 3 && is_name(parts[0]) && is_name(parts[2])) {
    return std::string(parts[0]) + ":" + std::string(parts[2]);
  }
  value.fail("'" + text +
             "' is not a CRS as CityJSON names one: "
             "https://www.opengis.net/def/crs/EPSG/0/7415 (or in version 1.0 "
             "urn:ogc:def:crs:EPSG::7415)");
}

}  // namespace shadowgen::cityjson::detail
