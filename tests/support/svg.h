#pragma once

// A tiny SVG writer for pictures of failing cases: each layer is a region drawn with
// the even-odd rule (so holes show), y pointing up, fitted to the union of the layers'
// bounding boxes. Best effort: a file that cannot be written is silently skipped.

#include <string>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::test {

struct SvgLayer {
  const clipper::PolygonSet2* polygons;
  std::string fill;    // an SVG colour, e.g. "#4c72b0" or "none"
  std::string stroke;  // an SVG colour
  std::string label;   // shown in the legend
};

void write_svg(const std::string& path, const std::vector<SvgLayer>& layers);

}  // namespace shadowgen::test
