#pragma once

// The scene as shadowgen models it (docs/scene-format.md, `shadowgen-scene/1`):
// faces in 3D with their ids, lights and optional views.

#include <cstddef>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/source_model.h"

namespace shadowgen {

// Relative planarity tolerance: a polygon is planar when every vertex lies within
// kPlanarityTolerance × (its size) of its best-fit plane, its size being the smaller of
// its largest extent and its width (area / largest extent). A triangle is planar.
inline constexpr double kPlanarityTolerance = 1e-9;

// One face of the scene. Its front side is the side from which the outer loop of each
// part runs counter-clockwise. A planar face has one part per piece of its region (holes
// sharing edges can cut it apart); a non-planar polygon is split into triangles (same id).
struct Face {
  std::string id;
  std::vector<hsr::Polygon3> parts;
  std::string source_file;  // the scene or mesh file it came from, for messages
  FaceOrigin origin = {};   // where a model file's face comes from; empty otherwise
  // How far its source's written precision lets a vertex stray (SourceFace::
  // vertex_rounding, in scene coordinates): a part within twice this of its plane is
  // planar. 0 for a scene's own polygons and meshes' faces.
  double vertex_rounding = 0.0;
};

enum class LightType { kDirectional, kPoint };

// Fall-off of a point light: full intensity up to falloff_start, zero from end on.
struct LightRange {
  double falloff_start = 0.0;
  double end = 0.0;
  double exponent = 2.0;
};

// What a directional light placed by a `sun` entry stands for (docs/scene-format.md, "Site
// and sun path"): one instant of the entry, kept for what sums over a sun path (sun hours,
// shading schedules) and for listing the instants.
struct SunInstant {
  std::string sun_id;          // the `sun` entry's id; the light's is `<sun_id>@<YYYY-MM-DDTHH:MM>`
                               // for a sun path, sun_id itself for a single `time`
  std::string time;            // local standard time, `YYYY-MM-DDTHH:MM`, `:SS` added when not 0
  int step_min = 0;            // the minutes the instant stands for in a sun path; 0 for a `time`
  double azimuth_deg = 0.0;    // clockwise from true north
  double elevation_deg = 0.0;  // apparent (refraction included), above 0
  // For a sun path's instant, the path's span as its entry gives it (`from`, `to`, local
  // standard time, written as `time` is); empty for a `time`.
  std::string path_from = {}, path_to = {};
};

struct Light {
  std::string id;
  LightType type = LightType::kDirectional;
  // directional: the way the light travels; the reader scales it by a power of two
  // (exact) so that its largest component lies in [0.5, 1).
  glm::dvec3 direction{0.0, 0.0, -1.0};
  glm::dvec3 position{0.0};  // point
  glm::dvec3 intensity{1.0, 1.0, 1.0};
  std::optional<LightRange> range;  // point lights only
  std::optional<SunInstant> sun;    // directional lights a `sun` entry placed
};

// A `sun` entry with from, to and step_min (docs/scene-format.md, "Site and sun path"): a
// sun path. Its instants are the lights whose Light::sun names it, those with the sun up;
// it may have none (the sun below the horizon at every step, a polar night) and is a path
// all the same, whose every step has no sun.
struct SunPathSpan {
  std::string id;
  int step_min = 0;      // positive
  std::string from, to;  // local standard time, written as SunInstant::time is
};

// Whether `light` is an instant of a sun path (a `sun` entry's from/to/step_min), not a
// light of its own.
inline bool in_sun_path(const Light& light) { return light.sun && light.sun->step_min > 0; }

struct ViewSpec {
  std::string id;
  glm::dvec3 eye{0.0};
  glm::dvec3 target{0.0};
  glm::dvec3 up{0.0, 0.0, 1.0};
  double fov_deg = 45.0;
};

// Where the scene stands on the Earth, and how it is turned.
struct Site {
  double latitude_deg = 0.0;    // north-positive, [-90, 90]
  double longitude_deg = 0.0;   // east-positive, [-180, 180]
  double elevation_m = 0.0;     // above sea level
  double utc_offset_h = 0.0;    // local standard time minus UTC, no daylight saving
  double north_axis_deg = 0.0;  // from true north to the scene's +y, clockwise from above
};

// One hourly row of an EnergyPlus weather file (docs/scene-format.md, "Weather file"): what
// irradiation outputs need of it. The file's year is not kept: typical-year files mix
// years, and rows are found by month, day and hour.
struct WeatherHour {
  int month = 1;   // 1 to 12
  int day = 1;     // 1 to the month's length; February 29 may be present
  int hour = 1;    // 1 to 24: the hour from (hour - 1):00 to hour:00, local standard time
  int minute = 0;  // as the file gives it, 0 to 60; not used for timing
  // Over the hour, on a surface facing the sun: Wh/m2, which is also the hour's mean
  // irradiance in W/m2. nullopt where the file marks it missing (9999 or more) or gives a
  // negative value; an error only when an instant needs it.
  std::optional<double> direct_normal_wh_m2;
  // The same for the global horizontal and the diffuse horizontal radiation, over the hour
  // on a horizontal surface (Wh/m2, the hour's mean in W/m2), missing as above.
  std::optional<double> global_horizontal_wh_m2;
  std::optional<double> diffuse_horizontal_wh_m2;
  // The ground's albedo, 0 to 1; nullopt where the file marks it missing (999 or more).
  std::optional<double> albedo;
  std::size_t line = 0;  // in the file, for messages
};

// An EnergyPlus weather file as read (shadowgen/weather/epw_reader.h).
struct Weather {
  std::string file;  // as messages name it
  // The LOCATION header's text fields, as written (spaces around them removed).
  std::string city, state_province, country, source, wmo;
  Site site;                       // from the LOCATION header; north_axis_deg 0
  std::vector<WeatherHour> hours;  // in file order: each the hour after the one before
};

// A named set of faces (docs/scene-format.md, "Groups"): a scene's `groups` entry, kept in
// the database, which reports sum over. Which faces it holds is the face patterns' rule
// (shadowgen/groups/face_pattern.h): every face whose id one of `patterns` matches.
struct FaceGroupSpec {
  std::string id;                     // unique among the scene's groups
  std::vector<std::string> patterns;  // at least one, each matching some face
  bool operator==(const FaceGroupSpec&) const = default;
};

struct Scene {
  // The file it was read from, as messages about the whole input name it: the scene, or
  // the shadowed database the user gave (never the scene a database was generated from;
  // a face's own file is Face::source_file); "-" for standard input.
  std::string file;
  std::vector<Face> faces;  // polygons first, then mesh faces, in file order
  // In file order; a `sun` entry is its instants, in time order, where it stood.
  std::vector<Light> lights;
  // The sun paths, in file order (the order of their instants among the lights), those
  // without an instant included.
  std::vector<SunPathSpan> sun_paths;
  std::vector<ViewSpec> views;
  std::vector<FaceGroupSpec> groups;  // in file order
  std::optional<Site> site;           // the scene's own, or else its weather file's
  std::optional<Weather> weather;
  // Every file the scene was read from, in reading order, as messages name them: the
  // scene file, then each mesh file, then the weather file. Empty for the scene a
  // shadowed database holds, which names files it was once read from but reads none.
  std::vector<std::string> files;
};

}  // namespace shadowgen
