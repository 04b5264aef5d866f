#include "shadowgen/output/hour_bands.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "shadowgen/model/number_text.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen {
namespace {

// matplotlib's viridis (Stéfan van der Walt and Nathaniel Smith, 2015) at t = 0, 1/8, ...,
// 1, as matplotlib.colors.to_hex(matplotlib.colormaps["viridis"](i / 8)) gives them; the
// ramp interpolates linearly between them in sRGB, as matplotlib does between the entries
// of its own table, and stays within a few units of 255 of it.
constexpr std::array<std::uint32_t, 9> kViridis{0x440154, 0x472d7b, 0x3b528b, 0x2c728e, 0x21918c,
                                                0x28ae80, 0x5ec962, 0xaddc30, 0xfde725};

glm::dvec3 control_colour(std::size_t i) {
  const std::uint32_t c = kViridis[i];
  return glm::dvec3((c >> 16) & 0xff, (c >> 8) & 0xff, c & 0xff) / 255.0;
}

// The band widths of the default edges, in hundredths of an hour, from the narrowest: the
// round numbers of hours listed in hour_bands.h. Whole numbers, so that an edge is one
// division (k × width / 100) and compares with the database's hours exactly.
std::uint64_t ladder_width(std::size_t i) {
  constexpr std::array<std::uint64_t, 15> kHours{1,   2,   5,   10,  20,  25,   50,  100,
                                                 200, 300, 400, 600, 800, 1200, 2400};
  if (i < kHours.size()) return kHours[i];
  // Then days: 2, 5, 10, 20, 50, 100, ...
  i -= kHours.size();
  constexpr std::array<std::uint64_t, 3> kSteps{2, 5, 10};
  std::uint64_t width = 2400 * kSteps[i % 3];
  for (std::size_t decade = 0; decade < i / 3; ++decade) width *= 10;
  return width;
}

void check_edges(std::span<const double> edges, const HourBands& bands) {
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const double e = edges[i];
    if (!std::isfinite(e) || !(e > 0.0)) {
      throw std::invalid_argument("a band edge must be a finite number of hours above 0, not " +
                                  shortest(e));
    }
    if (i > 0 && !(edges[i - 1] < e)) {
      throw std::invalid_argument("band edges must be in increasing order (" +
                                  shortest(edges[i - 1]) + " before " + shortest(e) + ")");
    }
    if (e > bands.most_hours) {
      throw std::invalid_argument("the band edge " + shortest(e) + " is above the " +
                                  shortest(bands.most_hours) + " h that sun path '" +
                                  one_line(bands.path_id) + "' gives at most");
    }
  }
}

// Colours at the centre of the hours each band can hold (hour_bands.h).
void colour_bands(HourBands& bands) {
  constexpr double kNone = -1.0;
  std::vector<double> least(bands.bands.size(), kNone), most(bands.bands.size(), kNone);
  for (std::size_t count = 0; count <= bands.instants; ++count) {
    const double hours = static_cast<double>(count) * bands.step_min / 60.0;
    const std::size_t b = bands.band_of(hours);
    if (least[b] == kNone) least[b] = hours;
    most[b] = hours;
  }
  for (std::size_t b = 0; b < bands.bands.size(); ++b) {
    HourBand& band = bands.bands[b];
    const double centre =
        least[b] == kNone ? 0.5 * (band.from + band.to) : 0.5 * (least[b] + most[b]);
    band.colour = sun_hours_ramp(bands.most_hours > 0.0 ? centre / bands.most_hours : 0.0);
  }
}

}  // namespace

std::size_t HourBands::band_of(double hours) const {
  std::size_t b = 0;
  while (b + 1 < bands.size() && bands[b + 1].from <= hours) ++b;
  return b;
}

std::vector<std::string> HourBands::caption() const {
  return {"Sun hours: " + one_line(path_id), std::to_string(instants) +
                                                 (instants == 1 ? " instant" : " instants") +
                                                 ", every " + std::to_string(step_min) + " min"};
}

std::vector<double> default_band_edges(int step_min, std::size_t instants) {
  if (step_min <= 0) throw std::invalid_argument("a sun path's step must be above 0 minutes");
  // In fifths of a minute times 3 (hundredths of an hour × 3 = minutes × 5), so that every
  // comparison is of whole numbers: width ≥ step is 3 width ≥ 5 step, and k × width ≤ the
  // most hours is 3 k width ≤ 5 × instants × step.
  const std::uint64_t step5 = 5 * static_cast<std::uint64_t>(step_min);
  const std::uint64_t total5 = step5 * instants;
  for (std::size_t i = 0;; ++i) {
    const std::uint64_t width = ladder_width(i);
    if (3 * width < step5) continue;
    const std::uint64_t edges = total5 / (3 * width);
    if (edges + 1 > kMaxDefaultBands) continue;
    std::vector<double> out;
    out.reserve(edges);
    for (std::uint64_t k = 1; k <= edges; ++k) {
      out.push_back(static_cast<double>(k * width) / 100.0);
    }
    return out;
  }
}

HourBands hour_bands(const SunPathHours& path, std::span<const double> edges) {
  HourBands bands;
  bands.path_id = path.id;
  bands.step_min = path.step_min;
  bands.instants = path.instants.size();
  // As the database's hours are: count × step_min / 60, the count a double.
  bands.most_hours = static_cast<double>(bands.instants) * path.step_min / 60.0;
  std::vector<double> chosen(edges.begin(), edges.end());
  if (chosen.empty()) {
    chosen = default_band_edges(path.step_min, bands.instants);
  } else {
    check_edges(chosen, bands);
  }
  std::vector<double> from{0.0};
  from.insert(from.end(), chosen.begin(), chosen.end());
  for (std::size_t b = 0; b < from.size(); ++b) {
    HourBand band;
    band.from = from[b];
    const bool last = b + 1 == from.size();
    band.to = last ? bands.most_hours : from[b + 1];
    if (last) {
      band.label = "\u2265 " + shortest(band.from) + " h";
      band.name = shortest(band.from) + "h+";
    } else {
      band.label = shortest(band.from) + "\u2013" + shortest(band.to) + " h";
      band.name = shortest(band.from) + "-" + shortest(band.to) + "h";
    }
    bands.bands.push_back(std::move(band));
  }
  colour_bands(bands);
  return bands;
}

glm::dvec3 sun_hours_ramp(double t) {
  const double x = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) * (kViridis.size() - 1) : 0.0;
  const std::size_t i = std::min(static_cast<std::size_t>(x), kViridis.size() - 2);
  const double f = x - static_cast<double>(i);
  return control_colour(i) + f * (control_colour(i + 1) - control_colour(i));
}

}  // namespace shadowgen
