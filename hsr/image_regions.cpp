#include "hsr/image_regions.h"

#include <algorithm>
#include <cmath>

namespace shadowgen::hsr {
namespace {

constexpr std::size_t kPiecesPerRegion = 4096;
constexpr std::size_t kMaxRegions = 256;

// `parts` - 1 cuts at quantiles of `values` (reordered here), strictly increasing and
// strictly inside (lo, hi); fewer where values repeat.
std::vector<double> quantile_cuts(std::vector<double> values, std::size_t parts, double lo,
                                  double hi) {
  // Each quantile put in its place, the values below it before it: the cuts a full sort
  // would give, without sorting all of them.
  std::vector<double> cuts{lo};
  auto sorted_from = values.begin();
  for (std::size_t k = 1; k < parts; ++k) {
    const auto at = values.begin() + static_cast<std::ptrdiff_t>(k * values.size() / parts);
    std::nth_element(sorted_from, at, values.end());
    sorted_from = at;
    const double cut = *at;
    if (cut > cuts.back() && cut < hi) cuts.push_back(cut);
  }
  cuts.push_back(hi);
  return cuts;
}

}  // namespace

std::size_t region_count_for(std::size_t pieces) {
  if (pieces < 2 * kPiecesPerRegion) return 1;
  return std::min(kMaxRegions, pieces / kPiecesPerRegion);
}

std::vector<clipper::Box2> image_regions(std::span<const clipper::Box2> boxes, std::size_t count) {
  if (boxes.empty()) return {};
  clipper::Box2 extent;
  for (const clipper::Box2& b : boxes) extent.add(b);
  if (count <= 1) return {extent};
  // Columns and rows in proportion to the image's sides.
  const double width = extent.xmax - extent.xmin, height = extent.ymax - extent.ymin;
  const double aspect = height > 0.0 ? width / height : 1.0;
  const double ideal = std::sqrt(static_cast<double>(count) * std::clamp(aspect, 1e-6, 1e6));
  const auto columns =
      static_cast<std::size_t>(std::clamp(std::round(ideal), 1.0, static_cast<double>(count)));
  const std::size_t rows = std::max<std::size_t>(1, count / columns);
  std::vector<double> xs, ys;
  xs.reserve(boxes.size());
  ys.reserve(boxes.size());
  for (const clipper::Box2& b : boxes) {
    xs.push_back(0.5 * b.xmin + 0.5 * b.xmax);
    ys.push_back(0.5 * b.ymin + 0.5 * b.ymax);
  }
  const std::vector<double> x_cuts =
      quantile_cuts(std::move(xs), columns, extent.xmin, extent.xmax);
  const std::vector<double> y_cuts = quantile_cuts(std::move(ys), rows, extent.ymin, extent.ymax);
  std::vector<clipper::Box2> regions;
  for (std::size_t j = 0; j + 1 < y_cuts.size(); ++j) {
    for (std::size_t i = 0; i + 1 < x_cuts.size(); ++i) {
      regions.push_back({x_cuts[i], y_cuts[j], x_cuts[i + 1], y_cuts[j + 1]});
    }
  }
  return regions;
}

}  // namespace shadowgen::hsr
