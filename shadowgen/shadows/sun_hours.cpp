#include "shadowgen/shadows/sun_hours.h"

#include <algorithm>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/merge.h"
#include "clipper/normalize.h"
#include "hsr/area.h"

namespace shadowgen {

FaceSunHours::FaceSunHours(const Face& face) {
  for (std::size_t k = 0; k < face.parts.size(); ++k) {
    const hsr::Plane3 plane = hsr::plane_of(face.parts[k]);
    if (plane.normal == glm::dvec3(0.0) || !(hsr::area(face.parts[k]) > 0.0)) continue;
    // The part's own vertices are lifted back to themselves exactly; lit polygons are
    // charted exactly but not remembered (the part's plane places their vertices).
    Part part{k,
              face.parts[k],
              hsr::ChartedPlane(plane.normal, face.parts[k].outer[0], hsr::ChartFrom::kWorld),
              {},
              {}};
    part.whole = clipper::normalized({part.chart.flatten_known(face.parts[k])});
    if (part.whole.empty()) continue;  // no area in its chart either
    part.by_count.push_back({0, part.whole});
    parts_.push_back(std::move(part));
  }
}

namespace {

// Whether two loops are the same points in the same cyclic order.
bool same_loop(const hsr::Loop3& a, const hsr::Loop3& b) {
  if (a.size() != b.size() || a.empty()) return a.size() == b.size();
  const auto start = std::find(b.begin(), b.end(), a.front());
  if (start == b.end()) return false;
  const std::size_t offset = static_cast<std::size_t>(start - b.begin());
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] != b[(i + offset) % b.size()]) return false;
  }
  return true;
}

// Whether a lit polygon is its part itself, vertex for vertex: the part lit whole, as
// generation gives it where nothing shades the part.
bool is_whole_part(const hsr::Polygon3& lit, const hsr::Polygon3& part) {
  if (!same_loop(lit.outer, part.outer) || lit.holes.size() != part.holes.size()) return false;
  for (std::size_t h = 0; h < part.holes.size(); ++h) {
    if (!same_loop(lit.holes[h], part.holes[h])) return false;
  }
  return true;
}

std::vector<clipper::Box2> boxes_of(const clipper::PolygonSet2& polygons) {
  std::vector<clipper::Box2> boxes;
  boxes.reserve(polygons.size());
  for (const clipper::PolygonWithHoles2& p : polygons) boxes.push_back(clipper::box_of(p));
  return boxes;
}

bool overlaps_any(const clipper::Box2& box, const std::vector<clipper::Box2>& boxes) {
  return std::any_of(boxes.begin(), boxes.end(),
                     [&box](const clipper::Box2& b) { return b.overlaps(box); });
}

}  // namespace

void FaceSunHours::add(std::span<const LitPolygon> lit) {
  for (Part& part : parts_) {
    std::vector<const hsr::Polygon3*> on_part;
    for (const LitPolygon& q : lit) {
      if (q.part == part.index && q.polygon.outer.size() >= 3) on_part.push_back(&q.polygon);
    }
    if (on_part.empty()) continue;  // unlit at this instant: every count stays
    if (on_part.size() == 1 && is_whole_part(*on_part[0], part.polygon)) {
      for (CountPieces& c : part.by_count) ++c.count;  // lit whole: every count goes up
      continue;
    }
    clipper::PolygonSet2 clips;
    for (const hsr::Polygon3* q : on_part) clips.push_back(part.chart.flatten(*q));
    // The part in shadow, so that pieces wholly lit are known by their boxes alone.
    const clipper::PolygonSet2 shadow = clipper::difference(part.whole, clips);
    const std::vector<clipper::Box2> lit_boxes = boxes_of(clips);
    const std::vector<clipper::Box2> shadow_boxes = boxes_of(shadow);

    // A piece that no lit polygon's box overlaps stays; one that no shadowed polygon's box
    // overlaps goes one up; the others, along the lit region's boundary, are split with
    // one clip per count. Over a sun path most pieces are far from an instant's shadow
    // edges, so the work per instant follows those edges, not the pieces.
    std::vector<CountPieces> next;
    const auto to = [&next](std::size_t count) -> clipper::PolygonSet2& {
      if (next.empty() || next.back().count != count) next.push_back({count, {}});
      return next.back().pieces;
    };
    clipper::PolygonSet2 carried;  // pieces of the count below that went one up
    for (std::size_t i = 0; i < part.by_count.size(); ++i) {
      CountPieces& c = part.by_count[i];
      clipper::PolygonSet2 stay = std::move(carried), up, split;
      carried.clear();
      for (clipper::PolygonWithHoles2& piece : c.pieces) {
        const clipper::Box2 box = clipper::box_of(piece);
        if (!overlaps_any(box, lit_boxes)) {
          stay.push_back(std::move(piece));
        } else if (!overlaps_any(box, shadow_boxes)) {
          up.push_back(std::move(piece));
        } else {
          split.push_back(std::move(piece));
        }
      }
      if (!split.empty()) {
        clipper::ClipResult r = clipper::clip(split, clips);
        for (auto& p : r.outside) stay.push_back(std::move(p));
        for (auto& p : r.inside) up.push_back(std::move(p));
      }
      if (!stay.empty()) to(c.count) = std::move(stay);
      const bool gap = i + 1 == part.by_count.size() || part.by_count[i + 1].count != c.count + 1;
      if (gap && !up.empty()) {
        to(c.count + 1) = std::move(up);
      } else {
        carried = std::move(up);  // joins the next count's pieces that stay
      }
    }
    part.by_count = std::move(next);
  }
}

std::vector<SunHoursRegion> FaceSunHours::regions(int step_min) const {
  std::map<std::size_t, std::vector<LitPolygon>> by_count;
  for (const Part& part : parts_) {
    for (const CountPieces& c : part.by_count) {
      std::vector<LitPolygon>& out = by_count[c.count];
      // Pieces of one count that different instants left side by side share edges.
      for (const clipper::PolygonWithHoles2& piece : clipper::merge_adjacent(c.pieces)) {
        out.push_back({part.index, part.chart.lift(piece)});
      }
    }
  }
  std::vector<SunHoursRegion> result;
  result.reserve(by_count.size());
  for (auto& [count, polygons] : by_count) {
    result.push_back({static_cast<double>(count) * step_min / 60.0, std::move(polygons)});
  }
  return result;
}

std::vector<SunPathHours> sun_paths_of(const Scene& scene) {
  std::vector<SunPathHours> paths;
  std::map<std::string, std::size_t> index;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const std::optional<SunInstant>& sun = scene.lights[l].sun;
    if (!sun || sun->step_min <= 0) continue;
    const auto [at, added] = index.emplace(sun->sun_id, paths.size());
    if (added) {
      SunPathHours path;
      path.id = sun->sun_id;
      path.step_min = sun->step_min;
      path.from = sun->path_from;
      path.to = sun->path_to;
      paths.push_back(std::move(path));
    }
    paths[at->second].instants.push_back(l);
  }
  return paths;
}

}  // namespace shadowgen
