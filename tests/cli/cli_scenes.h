#pragma once

// Scenes that more than one suite of the end-to-end tests runs `shadowgen` on.

namespace shadowgen::test {

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
