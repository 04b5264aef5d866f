#pragma once

// A file's metadata.referenceSystem as a CRS PROJ resolves: "EPSG:7415" from
// "https://www.opengis.net/def/crs/EPSG/0/7415" (CityJSON 1.1 and 2.0, "Metadata": an
// OGC CRS URL, http or https, {authority}/{version}/{code}) or from
// "urn:ogc:def:crs:EPSG::7415" (CityJSON 1.0: an OGC URN, {authority}:{version}:{code},
// the version often empty).

#include <string>

#include "shadowgen/json/json_reader.h"

namespace shadowgen::cityjson::detail {

// "AUTHORITY:code"; fails, at `value`, on a string of neither form.
std::string crs_of_reference_system(const JsonValue& value);

}  // namespace shadowgen::cityjson::detail
