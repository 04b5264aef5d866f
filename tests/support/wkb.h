#pragma once

// A small reader of hex-encoded Well-Known Binary for the areal types, as some JTS test
// files write their inputs: POLYGON (type 3) and MULTIPOLYGON (type 6), either byte
// order, PostGIS's SRID flag (EWKB, the SRID is skipped). Other types are reported as not
// areal. Z and M coordinates are not supported. Conventions as read_wkt: rings keep their
// orientation, the closing vertex is dropped, empty rings and polygons are skipped.
// Malformed input throws std::runtime_error.

#include <string_view>

#include "tests/support/wkt.h"

namespace shadowgen::test {

// True when the text (surrounding white space aside) is a hex string: WKB, not WKT.
bool looks_like_wkb_hex(std::string_view text);

ParsedGeometry read_wkb_hex(std::string_view hex);

}  // namespace shadowgen::test
