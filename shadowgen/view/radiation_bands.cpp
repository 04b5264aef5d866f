#include "shadowgen/view/radiation_bands.h"

#include <cmath>
#include <stdexcept>

#include "shadowgen/model/number_text.h"
#include "shadowgen/output/hour_bands.h"

namespace shadowgen {
namespace {

// m × 10^e, computed so that a negative e divides by an exact power of ten (0.2 is 2 / 10,
// not 2 × 0.1).
double round_width(int mantissa, int exponent) {
  const double power = std::pow(10.0, std::abs(exponent));
  return exponent < 0 ? mantissa / power : mantissa * power;
}

// The narrowest round width giving at most kMaxRadiationBands bands up to `most`.
double band_width(double most) {
  if (most <= 0.0) return 1.0;
  for (int exponent = static_cast<int>(std::floor(std::log10(most))) - 2;; ++exponent) {
    for (const int mantissa : {1, 2, 5}) {
      const double width = round_width(mantissa, exponent);
      if (std::ceil(most / width) <= static_cast<double>(kMaxRadiationBands)) return width;
    }
  }
}

}  // namespace

std::size_t RadiationBands::band_of(double kwh_per_m2) const {
  std::size_t band = 0;
  while (band + 1 < bands.size() && kwh_per_m2 >= bands[band + 1].from) ++band;
  return band;
}

std::vector<std::string> RadiationBands::caption() const {
  return {"Irradiation, kWh/m²: " + path_id, "direct + diffuse + ground"};
}

RadiationBands radiation_bands(const std::string& path_id, double most_kwh_per_m2) {
  if (!std::isfinite(most_kwh_per_m2) || most_kwh_per_m2 < 0.0) {
    throw std::invalid_argument(
        "the most irradiation of a radiation map must be finite and not "
        "negative, not " +
        shortest(most_kwh_per_m2));
  }
  RadiationBands result;
  result.path_id = path_id;
  result.width = band_width(most_kwh_per_m2);
  const auto count =
      static_cast<std::size_t>(std::max(1.0, std::ceil(most_kwh_per_m2 / result.width)));
  for (std::size_t i = 0; i < count; ++i) {
    RadiationBand band;
    band.from = static_cast<double>(i) * result.width;
    band.to = static_cast<double>(i + 1) * result.width;
    band.colour = sun_hours_ramp((static_cast<double>(i) + 0.5) / static_cast<double>(count));
    band.label = shortest(band.from) + "–" + shortest(band.to) + " kWh/m²";
    result.bands.push_back(band);
  }
  return result;
}

}  // namespace shadowgen
