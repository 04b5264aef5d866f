#include "clipper/tiles.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "detail/clip_prepared.h"

namespace shadowgen::clipper {
namespace {

// `count` − 1 cut positions splitting the sorted values `v` into `count` runs of about
// equal length, each halfway between two consecutive distinct values; fewer where the
// values repeat.
std::vector<double> quantile_cuts(std::vector<double> v, std::size_t count) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  std::vector<double> cuts;
  for (std::size_t k = 1; k < count; ++k) {
    const std::size_t i = k * v.size() / count;
    if (i == 0 || i >= v.size()) continue;
    const double c = std::midpoint(v[i - 1], v[i]);
    if (cuts.empty() || cuts.back() < c) cuts.push_back(c);
  }
  return cuts;
}

// The subject as clip_prepared takes it: spikes and repeats removed, straight-on vertices
// kept, outer loop counter-clockwise and holes clockwise. Empty when the outer loop has no
// area.
PolygonSet2 prepared(const PolygonWithHoles2& polygon) {
  PolygonWithHoles2 q{polygon.outer, {}};
  if (!remove_spikes(q.outer)) return {};
  if (!encloses_counter_clockwise(q.outer)) std::reverse(q.outer.begin(), q.outer.end());
  for (Loop2 hole : polygon.holes) {
    if (!remove_spikes(hole)) continue;
    if (encloses_counter_clockwise(hole)) std::reverse(hole.begin(), hole.end());
    q.holes.push_back(std::move(hole));
  }
  return {std::move(q)};
}

}  // namespace

PolygonSet2 split_into_tiles(const PolygonWithHoles2& polygon, std::size_t max_vertices) {
  const std::size_t n = vertex_count(polygon);
  if (n <= max_vertices || max_vertices == 0) return {polygon};
  PolygonSet2 subject = prepared(polygon);
  if (subject.empty()) return {polygon};

  // Cells of about max_vertices / 2 vertices each, as many across as the box's shape gives.
  const Box2 box = box_of(polygon);
  const double width = box.xmax - box.xmin;
  const double height = box.ymax - box.ymin;
  if (!(width > 0.0 && height > 0.0)) return {polygon};
  const double cells = std::ceil(2.0 * static_cast<double>(n) / static_cast<double>(max_vertices));
  const double across = std::clamp(std::round(std::sqrt(cells * width / height)), 1.0, cells);
  const double down = std::ceil(cells / across);
  std::vector<double> xs, ys;
  xs.reserve(n);
  ys.reserve(n);
  auto visit = [&](const Loop2& loop) {
    for (const Point2& p : loop) {
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
  };
  visit(polygon.outer);
  for (const Loop2& hole : polygon.holes) visit(hole);
  // The grid's lines: the cuts, framed by lines well outside the polygon's box.
  const double margin = std::max(width, height);
  std::vector<double> gx{box.xmin - margin}, gy{box.ymin - margin};
  for (const double c : quantile_cuts(std::move(xs), static_cast<std::size_t>(across))) {
    gx.push_back(c);
  }
  for (const double c : quantile_cuts(std::move(ys), static_cast<std::size_t>(down))) {
    gy.push_back(c);
  }
  gx.push_back(box.xmax + margin);
  gy.push_back(box.ymax + margin);
  if (gx.size() == 2 && gy.size() == 2) return {polygon};

  PolygonSet2 black;
  for (std::size_t i = 0; i + 1 < gx.size(); ++i) {
    for (std::size_t j = 0; j + 1 < gy.size(); ++j) {
      if ((i + j) % 2 != 0) continue;
      black.push_back(
          {{{gx[i], gy[j]}, {gx[i + 1], gy[j]}, {gx[i + 1], gy[j + 1]}, {gx[i], gy[j + 1]}}, {}});
    }
  }
  ClipResult split;
  try {
    split = detail::clip_prepared(std::move(subject), black);
  } catch (const SnapRoundingError&) {
    return {polygon};
  }
  PolygonSet2 tiles = std::move(split.inside);
  for (PolygonWithHoles2& p : split.outside) tiles.push_back(std::move(p));
  if (!encloses_counter_clockwise(polygon.outer)) {
    for (PolygonWithHoles2& tile : tiles) {
      std::reverse(tile.outer.begin(), tile.outer.end());
      for (Loop2& hole : tile.holes) std::reverse(hole.begin(), hole.end());
    }
  }
  return tiles;
}

}  // namespace shadowgen::clipper
