#pragma once

// A small reader of Well-Known Text for the areal types: POLYGON and MULTIPOLYGON,
// EMPTY included. Other geometry types (POINT, LINESTRING, GEOMETRYCOLLECTION, ...) are
// recognised by name and reported as not areal, without being parsed.
//
// Rings keep their file orientation (normalise before use); the closing vertex that
// repeats the first is dropped. An EMPTY ring or polygon inside a larger geometry is
// skipped. Numbers are read with strtod (correctly rounded to the nearest double).
// Z and M coordinates are not supported. Syntax errors throw std::runtime_error naming
// the offset and what was expected.

#include <string>
#include <string_view>

#include "clipper/polygon.h"

namespace shadowgen::test {

// A geometry as read from WKT (or WKB, tests/support/wkb.h).
struct ParsedGeometry {
  std::string type;    // upper case: "POLYGON", "MULTIPOLYGON", "POINT", ...
  bool areal = false;  // POLYGON or MULTIPOLYGON (possibly EMPTY)
  bool empty = false;  // written as EMPTY, or with no polygon left after skipping EMPTY parts
  clipper::PolygonSet2 polygons;  // only for areal types
};

ParsedGeometry read_wkt(std::string_view text);

// MULTIPOLYGON text with 17 significant digits, so that reading it back gives the same
// doubles: for printing a failing case in a form that can be pasted into a test.
std::string to_wkt(const clipper::PolygonSet2& polygons);

}  // namespace shadowgen::test
