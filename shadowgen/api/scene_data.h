#pragma once

// A scene held in memory as plain numbers and ids, for a program that makes its geometry
// itself (make_scene in shadowgen/api/scene.h). It means what the same scene written as a
// file means (docs/scene-format.md) and is checked by the same rules, with the same
// messages, naming SceneData::name as the file:
//
//   shadowgen::api::SceneData data;
//   data.faces.push_back({"ground", {{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}}});
//   data.faces.push_back({"roof", {{{2, 2, 3}, {6, 2, 3}, {6, 6, 3}, {2, 6, 3}}}});
//   data.lights.push_back({.id = "sun", .direction = {-0.3, 0.6, -1.0}});
//   shadowgen::api::Scene scene = shadowgen::api::make_scene(data);

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace shadowgen::api {

using Point = std::array<double, 3>;  // x, y, z in the scene's units
using Loop = std::vector<Point>;      // a closed loop, its last point not repeated

// A planar polygon with holes. Its front is the side from which `outer` runs
// counter-clockwise; holes run either way.
struct PolygonData {
  Loop outer = {};
  std::vector<Loop> holes = {};
};

struct FaceData {
  std::string id = {};  // unique in the scene
  PolygonData polygon = {};
};

enum class LightKind {
  kDirectional,  // `direction`: the way the light travels
  kPoint,        // `position`, and a range where given
  kSun,          // `time`, or `from`, `to` and `step_min`: the sun at a site (SceneData::site)
};

// A point light's fall-off: full intensity up to falloff_start, zero from end on.
struct RangeData {
  double falloff_start = 0.0;
  double end = 0.0;
  double exponent = 2.0;
};

struct LightData {
  std::string id = {};
  LightKind kind = LightKind::kDirectional;
  Point direction{0.0, 0.0, -1.0};      // kDirectional
  Point position{0.0, 0.0, 0.0};        // kPoint
  Point intensity{1.0, 1.0, 1.0};       // kDirectional and kPoint
  std::optional<RangeData> range = {};  // kPoint
  // kSun, local standard time "YYYY-MM-DDTHH:MM": one instant (`time`), or a sun path from
  // `from` to `to` every `step_min` minutes (an instant per step with the sun up).
  std::string time = {}, from = {}, to = {};
  int step_min = 0;
};

// Where the scene stands: what sun lights need.
struct SiteData {
  double latitude_deg = 0.0;    // north-positive
  double longitude_deg = 0.0;   // east-positive
  double elevation_m = 0.0;     // above sea level
  double utc_offset_h = 0.0;    // local standard time minus UTC
  double north_axis_deg = 0.0;  // from true north to the scene's +y, clockwise from above
};

// A named set of faces that reports sum over: every face one of `faces` matches (face
// patterns: `*` any run without `/`, `**` any run, `?` one character).
struct GroupData {
  std::string id = {};
  std::vector<std::string> faces = {};
};

struct SceneData {
  std::string name = "scene";  // names the scene in messages, as a file name would
  std::vector<FaceData> faces = {};
  std::vector<LightData> lights = {};
  std::optional<SiteData> site = {};
  std::vector<GroupData> groups = {};
};

}  // namespace shadowgen::api
