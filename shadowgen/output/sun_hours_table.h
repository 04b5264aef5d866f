#pragma once

// The sun-hours test for people (report --format sun-hours-table; docs/scene-format.md,
// "Sun-hours table"): per sun path and threshold, one line per group of faces (or per
// face, without groups) saying what share of its area gets at least that many hours of
// sun, and whether that passes the test of BRE 209 ("Site layout planning for daylight and
// sunlight", 2022, section 3.3): at least half of an amenity area should receive at least
// two hours of sunlight on 21 March.
//
//   sun path 'march21': 21 March 2026, 08:00 to 16:00, every 120 min
//   an area passes when at least 50 % of it gets at least the hours shown (BRE 209, 2022,
//   section 3.3: 2 h on 21 March) garden: 87.7 % of 412 m² gets ≥ 2 h on 21 March: passes

#include <span>
#include <string>
#include <string_view>

#include "shadowgen/groups/face_groups.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

// The share of an area that must get the hours for it to pass: BRE 209's "at least half".
inline constexpr double kSunTestPassShare = 0.5;

// One line: "<name>: <share> % of <area> m² gets ≥ <T> h <when>: passes" (or "fails"),
// passing where area_at_least ≥ kSunTestPassShare × area, exactly (at 50 % it passes).
// The share has one decimal, more where one would round a failing share up to 50.0; the
// area three significant digits below 100 and whole ones from there; T the shortest form
// of the threshold. An area of 0 gives "<name>: no area". `name` is written on one line
// (shadowgen/model/one_line.h). Areas are in the scene's unit squared, m² for metres.
std::string sun_test_line(std::string_view name, double area, double area_at_least,
                          double threshold, std::string_view when);

// When a path's instants fall, for the lines: "on 21 March" for a path within one day,
// else "from 21 March to 22 March" (years added where they differ). `from` and `to` are
// SunPathHours::from and ::to.
std::string sun_path_days(std::string_view from, std::string_view to);

// Per sun path, in order (a blank line between them): a line naming the path, its day and
// step, a line stating the test, then per group (or, without groups, per face in scene
// order) one sun_test_line per threshold. Throws what sun_hours_rows throws.
std::string sun_hours_table(const ShadowedScene& shadowed, std::span<const double> thresholds,
                            std::span<const groups::FaceGroup> groups = {});

}  // namespace shadowgen
