#pragma once

// Scenes that more than one suite of the end-to-end tests runs `shadowgen` on.

#include <string>
#include <vector>

#include "tests/shadowgen/weather/epw_text.h"

namespace shadowgen::test {

// A yard with a wall south of it, under the sun of 21 March from 10:00 to 14:00 at the
// weather file's site; its weather file is "march.epw" beside it (march_epw).
inline constexpr const char* kMarchYardScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "yard", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "wall", "outer": [[0,-0.5,0],[10,-0.5,0],[10,-0.5,4],[0,-0.5,4]]}
  ],
  "weather": "march.epw",
  "lights": [{"id": "march21", "type": "sun", "from": "2026-03-21T10:00",
              "to": "2026-03-21T14:00", "step_min": 60}]
})";

// 21 March, every hour 500 Wh/m² global, 400 direct normal, 150 diffuse horizontal, the
// albedo as `albedo` writes it.
inline std::string march_epw(const std::string& albedo) {
  std::vector<std::string> lines = epw_header();
  for (int h = 1; h <= 24; ++h) lines.push_back(epw_row(3, 21, h, "500", "400", "150", albedo));
  return joined(lines);
}

// A scene whose one polygon, "stub", has two vertices: reading it fails, naming "stub".
inline constexpr const char* kStubScene = R"({
    "format": "shadowgen-scene/1",
    "polygons": [{"id": "stub", "outer": [[0,0,0],[1,0,0]], "holes": []}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })";

// A scene whose one polygon, "bent", is a square with a corner lifted off its plane: it reads
// with a warning (an error under --strict) and is split into two triangles.
inline constexpr const char* kBentScene = R"({
    "format": "shadowgen-scene/1",
    "polygons": [{"id": "bent", "outer": [[0,0,0],[1,0,0],[1,1,0.5],[0,1,0]], "holes": []}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })";

}  // namespace shadowgen::test
