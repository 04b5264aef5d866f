#pragma once

// A scene's `sun` light (docs/scene-format.md, "Site and sun path"), as the directional
// lights it stands for, each carrying its SunInstant:
// - with "time": one light with the entry's id, the sun at that local standard time; the
//   sun at or below the horizon then is an error naming the light;
// - with "from", "to" and "step_min" (a positive whole number of minutes): one light per
//   instant from `from` to `to` inclusive whose apparent elevation is above 0, in time
//   order, named `<id>@<YYYY-MM-DDTHH:MM>`; a path with none (a polar night) is a path
//   all the same, and draws a warning.
// Every id is claimed in `ids`. A light's direction is the way the light travels: minus the
// vector toward the sun in scene axes (+z up, +y at `north_axis_deg` clockwise from true
// north), scaled like every directional light (Light::direction).
// Errors name the file, the light and the JSON path: no site, neither or both of the two
// forms, a time not `YYYY-MM-DDTHH:MM[:SS]` or beyond the year 6000, `to` before `from`,
// a step that is not a positive whole number of minutes, more than kMaxSunInstants.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "detail/json_entities.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::scene::detail {

// A year at one minute's step has 525,600.
inline constexpr std::size_t kMaxSunInstants = 1'000'000;

// Whether lights[i] is a `sun` entry (to be read here rather than by read_light).
bool is_sun_light(const JsonValue& value);

// The lights a `sun` entry places, and the sun path it is (with from, to and step_min;
// nullopt for a `time`), which stands even where no light does.
struct SunEntryRead {
  std::vector<Light> lights;
  std::optional<SunPathSpan> path;
};

// `site_incomplete` says, when there is no site, why the keys given make none
// (MergedSite::incomplete); empty when none is given.
SunEntryRead read_sun_light(const JsonValue& value, IdRegistry& ids,
                            const std::optional<Site>& site,
                            const std::string& site_incomplete = {});

}  // namespace shadowgen::scene::detail
