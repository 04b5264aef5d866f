#include "shadowgen/shadows/light_regions.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "clipper/clip.h"
#include "clipper/merge.h"
#include "clipper/normalize.h"
#include "hsr/area.h"
#include "hsr/plane_chart.h"
#include "shadowgen/model/scene.h"

namespace shadowgen {
namespace {

using LightSet = std::vector<std::size_t>;

// One part of a face in its exact plane chart, and the way back to 3D.
class PartChart {
 public:
  PartChart(const hsr::Polygon3& part, const hsr::Plane3& plane)
      : chart_(hsr::chart_facing(plane.normal)), plane_(plane), origin_(part.outer[0]) {
    const int d = chart_.dropped_axis;
    // The chart keeps a loop's turning sense exactly when the normal's dropped component is
    // positive (plane_chart.h); otherwise loops are reversed on the way back to 3D.
    reversed_ = plane.normal[d] < 0.0;
    add_original(part);
  }

  // The part's own vertices are lifted back to themselves exactly.
  void add_original(const hsr::Polygon3& polygon) {
    for (const glm::dvec3& p : polygon.outer) original_.emplace(chart_(p), p);
    for (const hsr::Loop3& h : polygon.holes) {
      for (const glm::dvec3& p : h) original_.emplace(chart_(p), p);
    }
  }

  clipper::PolygonWithHoles2 to_chart(const hsr::Polygon3& polygon) const {
    clipper::PolygonWithHoles2 out{to_chart(polygon.outer), {}};
    for (const hsr::Loop3& h : polygon.holes) out.holes.push_back(to_chart(h));
    return out;
  }

  hsr::Polygon3 lift(const clipper::PolygonWithHoles2& polygon) const {
    hsr::Polygon3 out{lift(polygon.outer), {}};
    for (const clipper::Loop2& h : polygon.holes) out.holes.push_back(lift(h));
    return out;
  }

 private:
  clipper::Loop2 to_chart(const hsr::Loop3& loop) const {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) out.push_back(chart_(p));
    return out;
  }

  // The dropped coordinate from the plane, relative to a vertex of the part so that far
  // from the origin the products do not cancel. The kept coordinates are the chart
  // point's own, so charting a lifted point gives back the very same chart point.
  glm::dvec3 lift(const clipper::Point2& q) const {
    if (const auto it = original_.find(q); it != original_.end()) return it->second;
    const int d = chart_.dropped_axis, i = (d + 1) % 3, j = (d + 2) % 3;
    const glm::dvec3& n = plane_.normal;
    glm::dvec3 p(0.0);
    p[i] = q.x;
    p[j] = q.y;
    p[d] = origin_[d] - (n[i] * (q.x - origin_[i]) + n[j] * (q.y - origin_[j])) / n[d];
    return p;
  }

  hsr::Loop3 lift(const clipper::Loop2& loop) const {
    hsr::Loop3 out;
    out.reserve(loop.size());
    for (const clipper::Point2& q : loop) out.push_back(lift(q));
    if (reversed_) std::reverse(out.begin(), out.end());
    return out;
  }

  hsr::PlaneChart chart_;
  hsr::Plane3 plane_;
  glm::dvec3 origin_;
  bool reversed_ = false;
  std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> original_;
};

}  // namespace

std::vector<LightRegion> light_regions(const ShadowedScene& shadowed, std::size_t face) {
  const Scene& scene = shadowed.scene;
  if (face >= scene.faces.size()) {
    throw std::invalid_argument("light_regions: face index " + std::to_string(face) +
                                " out of range");
  }
  if (shadowed.lit.size() != scene.faces.size() ||
      shadowed.lit[face].size() != scene.lights.size()) {
    throw std::invalid_argument("light_regions: lit detail polygons not shaped [face][light]");
  }
  const Face& f = scene.faces[face];
  const std::vector<std::vector<LitPolygon>>& lit = shadowed.lit[face];

  // Parts with area, with their planes.
  std::vector<std::size_t> parts;
  std::vector<hsr::Plane3> planes(f.parts.size());
  for (std::size_t k = 0; k < f.parts.size(); ++k) {
    planes[k] = hsr::plane_of(f.parts[k]);
    if (planes[k].normal != glm::dvec3(0.0) && area(f.parts[k]) > 0.0) parts.push_back(k);
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
  for (const std::size_t k : parts) {
    PartChart chart(f.parts[k], planes[k]);
    std::vector<std::pair<LightSet, clipper::PolygonSet2>> regions;
    regions.emplace_back(LightSet{}, clipper::normalized({chart.to_chart(f.parts[k])}));
    if (regions.back().second.empty()) continue;  // no area in its chart either

    for (std::size_t l = 0; l < lit.size(); ++l) {
      if (lit_by_part[k][l].empty()) continue;
      std::vector<clipper::PolygonWithHoles2> clips;
      for (const hsr::Polygon3* q : lit_by_part[k][l]) clips.push_back(chart.to_chart(*q));
      std::vector<std::pair<LightSet, clipper::PolygonSet2>> split;
      for (auto& [set, pieces] : regions) {
        clipper::PolygonSet2 inside, outside;
        for (const clipper::PolygonWithHoles2& piece : pieces) {
          clipper::ClipResult r = clipper::clip(piece, clips);
          for (auto& p : r.inside) inside.push_back(std::move(p));
          for (auto& p : r.outside) outside.push_back(std::move(p));
        }
        if (!outside.empty()) split.emplace_back(set, std::move(outside));
        if (!inside.empty()) {
          LightSet with = set;
          with.push_back(l);  // lights are taken in increasing order: stays sorted
          split.emplace_back(std::move(with), std::move(inside));
        }
      }
      regions = std::move(split);
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
