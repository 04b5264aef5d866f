#include "shadowgen/shadows/light_regions.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "clipper/clip.h"
#include "clipper/merge.h"
#include "clipper/normalize.h"
#include "detail/chart_region.h"
#include "hsr/area.h"
#include "hsr/plane_chart.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {
namespace {

using LightSet = std::vector<std::size_t>;
using SetPieces = std::vector<std::pair<LightSet, clipper::PolygonSet2>>;

// Every set's pieces split by light l's region: the pieces inside go to the set with l
// added, those outside stay (detail/chart_region.h: only pieces along l's shadow edges
// are clipped).
SetPieces split_by_light(SetPieces regions, const shadows::detail::ChartRegion& region,
                         std::size_t l) {
  SetPieces split;
  for (auto& [set, pieces] : regions) {
    clipper::PolygonSet2 inside, outside;
    region.split(std::move(pieces), outside, inside);
    if (!outside.empty()) split.emplace_back(set, std::move(outside));
    if (!inside.empty()) {
      LightSet with = set;
      with.push_back(l);  // lights are taken in increasing order: stays sorted
      split.emplace_back(std::move(with), std::move(inside));
    }
  }
  return split;
}

}  // namespace

namespace {

std::vector<LightRegion> regions_of(const ShadowedScene& shadowed, std::size_t face) {
  const Scene& scene = shadowed.scene();
  if (face >= scene.faces.size()) {
    throw std::invalid_argument("light_regions: face index " + std::to_string(face) +
                                " out of range");
  }
  const Face& f = scene.faces[face];
  const LitTable::ConstRow lit = shadowed.lit()[face];

  // Parts with area, each in its own chart: the part's vertices are lifted back to
  // themselves exactly; the lit polygons are charted exactly but not remembered (the
  // part's plane places their vertices).
  std::vector<std::pair<std::size_t, hsr::OwnChart>> parts;
  for (std::size_t k = 0; k < f.parts.size(); ++k) {
    if (std::optional<hsr::OwnChart> own = hsr::own_chart(f.parts[k])) {
      parts.emplace_back(k, std::move(*own));
    }
  }
  if (parts.empty()) return {};

  // Each lit polygon lies on the part it carries.
  std::vector<std::vector<std::vector<const hsr::Polygon3*>>> lit_by_part(
      f.parts.size(), std::vector<std::vector<const hsr::Polygon3*>>(lit.size()));
  for (std::size_t l = 0; l < lit.size(); ++l) {
    for (const LitPolygon& q : lit[l]) {
      if (q.polygon.outer.size() < 3 || q.part >= f.parts.size()) continue;
      lit_by_part[q.part][l].push_back(&q.polygon);
    }
  }

  std::map<LightSet, std::vector<LitPolygon>, LightSetLess> by_set;
  for (const auto& [k, own] : parts) {
    const hsr::ChartedPlane& chart = own.chart;
    const clipper::PolygonSet2 whole = clipper::normalized({own.flat});
    if (whole.empty()) continue;  // no area in its chart either
    SetPieces regions;
    regions.emplace_back(LightSet{}, whole);
    for (std::size_t l = 0; l < lit.size(); ++l) {
      if (lit_by_part[k][l].empty()) continue;
      clipper::PolygonSet2 clips;
      for (const hsr::Polygon3* q : lit_by_part[k][l]) clips.push_back(chart.flatten(*q));
      regions = split_by_light(std::move(regions),
                               shadows::detail::ChartRegion(whole, std::move(clips)), l);
    }

    // Pieces of one set cut by different lit polygons of a light share edges: merged.
    for (const auto& [set, pieces] : regions) {
      std::vector<LitPolygon>& out = by_set[set];
      for (const clipper::PolygonWithHoles2& piece : clipper::merge_adjacent(pieces)) {
        out.push_back({k, chart.lift(piece)});
      }
    }
  }

  std::vector<LightRegion> result;
  result.reserve(by_set.size());
  for (auto& [set, polygons] : by_set) {
    if (!polygons.empty()) result.push_back({set, std::move(polygons)});
  }
  return result;
}

}  // namespace

std::vector<LightRegion> light_regions(const ShadowedScene& shadowed, std::size_t face) {
  try {
    return regions_of(shadowed, face);
  } catch (const clipper::SnapRoundingError& e) {
    // Never a silently wrong region: the face is named, as generation names it.
    throw GenerationError("", shadowed.scene().faces[face].id, "",
                          "light-set regions not computed: " + std::string(e.what()));
  }
}

std::string light_set_name(const Scene& scene, std::span<const std::size_t> lights) {
  if (lights.empty()) return "shadow";
  std::string name;
  for (const std::size_t l : lights) {
    if (!name.empty()) name += '+';
    name += scene.lights.at(l).id;
  }
  return name;
}

}  // namespace shadowgen
