#pragma once

// The bands of a radiation map (radiation_map.h, docs/radiation.md "Radiation maps"): a
// sun path's range of total irradiation per face, 0 to the most any face gets (kWh/m²),
// cut into bands of one round width, each coloured by the sun-hours maps' ramp
// (sun_hours_ramp, viridis) and labelled for the legend.
//
// The width is the narrowest of 1, 2 and 5 × 10^k kWh/m² that covers the most with at most
// kMaxRadiationBands bands; band i holds the values v with i·width <= v < (i + 1)·width,
// the last band also its upper edge. Band i's colour is the ramp at (i + 1/2) / bands, so
// the bands' colours are evenly spaced from the ramp's dark end to its bright end.

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadowgen {

inline constexpr std::size_t kMaxRadiationBands = 10;

struct RadiationBand {
  double from = 0.0;       // kWh/m², included
  double to = 0.0;         // kWh/m², excluded (included for the last band)
  glm::dvec3 colour{0.0};  // sRGB, each channel in [0, 1]
  std::string label;       // UTF-8: "200–400 kWh/m²"
};

struct RadiationBands {
  std::string path_id;
  double width = 1.0;                // kWh/m²
  std::vector<RadiationBand> bands;  // in increasing values; at least one

  // The band holding `kwh_per_m2` (the first below 0, the last above the most).
  std::size_t band_of(double kwh_per_m2) const;

  // What a legend says above the bands: "Irradiation, kWh/m²: <path id>" and
  // "direct + diffuse + ground".
  std::vector<std::string> caption() const;
};

// The bands for values from 0 to `most_kwh_per_m2` (finite, at least 0; 0 gives one band
// of width 1). Throws std::invalid_argument for a negative or non-finite most.
RadiationBands radiation_bands(const std::string& path_id, double most_kwh_per_m2);

}  // namespace shadowgen
