#pragma once

// The hour bands of a sun-hours map (docs/scene-format.md, "Sun-hours maps"): a sun path's
// range of sun hours, 0 to the most a point can get (instants × step_min / 60), cut into
// bands, each with a colour of one ramp and a label. Drawn by `render --sun-hours` and
// written by `export --sun-hours`; both take their bands from here, so a picture and a
// model of one path agree, and every map of one path with the same bands is coloured the
// same.
//
// Bands are given by their edges e_1 < ... < e_k (hours, 0 < e_i <= the most hours): band 0
// holds the hours h with 0 <= h < e_1, band i those with e_i <= h < e_(i+1), the last
// those with h >= e_k. The default edges are the multiples of a width from a ladder of
// round numbers of hours (0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1, 2, 3, 4, 6, 8, 12, 24
// hours, then 2, 5, 10, 20, 50, ... days): the narrowest width, no narrower than the
// path's step, that gives at most kMaxDefaultBands bands. Each edge is k × width, computed
// as one division of whole numbers, as the database's hours are (count × step_min / 60),
// so that an edge and the hours equal to it compare equal.
//
// Colours: the ramp (sun_hours_ramp) at the centre of the hours a band can hold, over the
// most hours (the midpoint of the least and most multiples of the step inside the band;
// the midpoint of the band where it can hold none). The path's hours being discrete, a
// first band that holds only 0 h is the ramp's dark end, and a last band that holds only
// the most hours its bright end.

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

inline constexpr std::size_t kMaxDefaultBands = 12;

struct HourBand {
  double from = 0.0;       // least hours in the band (included)
  double to = 0.0;         // the next band's `from` (excluded); the last band's: the most hours
  glm::dvec3 colour{0.0};  // sRGB, each channel in [0, 1]
  std::string label;       // for people, UTF-8: "2–4 h"; the last band "≥ 10 h"
  std::string name;        // for file formats, ASCII: "2-4h"; the last band "10h+"
};

struct HourBands {
  std::string path_id;
  int step_min = 0;
  std::size_t instants = 0;
  double most_hours = 0.0;      // instants × step_min / 60
  std::vector<HourBand> bands;  // in increasing hours; at least one

  // The band holding `hours` (the last for hours beyond the most).
  std::size_t band_of(double hours) const;

  // What a legend says above the bands: "Sun hours: <path id>" and
  // "<n> instants, every <step_min> min".
  std::vector<std::string> caption() const;
};

// The bands of `path` with the edges `edges` (hours; empty: the default edges). Throws
// std::invalid_argument, saying why, for edges that are not finite, not above 0, not in
// increasing order or above the path's most hours.
HourBands hour_bands(const SunPathHours& path, std::span<const double> edges = {});

// The default edges of a path of `instants` instants `step_min` minutes apart (above).
std::vector<double> default_band_edges(int step_min, std::size_t instants);

// The colour ramp at t in [0, 1] (clamped), sRGB: matplotlib's viridis, perceptually
// ordered (lightness grows with t) and readable with the common colour-vision deficiencies.
glm::dvec3 sun_hours_ramp(double t);

}  // namespace shadowgen
