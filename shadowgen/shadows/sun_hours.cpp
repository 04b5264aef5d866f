#include "shadowgen/shadows/sun_hours.h"

#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "clipper/merge.h"
#include "clipper/normalize.h"
#include "detail/piece_split.h"
#include "hsr/area.h"

namespace shadowgen {

FaceSunHours::FaceSunHours(const Face& face) {
  for (std::size_t k = 0; k < face.parts.size(); ++k) {
    const hsr::Plane3 plane = hsr::plane_of(face.parts[k]);
    if (plane.normal == glm::dvec3(0.0) || !(hsr::area(face.parts[k]) > 0.0)) continue;
    // The part's own vertices are lifted back to themselves exactly; lit polygons are
    // charted exactly but not remembered (the part's plane places their vertices).
    Part part{
        k, hsr::ChartedPlane(plane.normal, face.parts[k].outer[0], hsr::ChartFrom::kWorld), {}};
    clipper::PolygonSet2 whole = clipper::normalized({part.chart.flatten_known(face.parts[k])});
    if (whole.empty()) continue;  // no area in its chart either
    part.by_count.push_back({0, std::move(whole)});
    parts_.push_back(std::move(part));
  }
}

void FaceSunHours::add(std::span<const LitPolygon> lit) {
  for (Part& part : parts_) {
    std::vector<clipper::PolygonWithHoles2> clips;
    for (const LitPolygon& q : lit) {
      if (q.part == part.index && q.polygon.outer.size() >= 3) {
        clips.push_back(part.chart.flatten(q.polygon));
      }
    }
    if (clips.empty()) continue;  // unlit at this instant: every count stays
    const detail::LitClips lit_clips(std::move(clips));

    // Each count's pieces split: those outside keep their count, those inside go one up.
    std::map<std::size_t, std::vector<clipper::PolygonSet2>> next;
    for (CountPieces& c : part.by_count) {
      clipper::PolygonSet2 inside, outside;
      lit_clips.split(c.pieces, inside, outside);
      if (!outside.empty()) next[c.count].push_back(std::move(outside));
      if (!inside.empty()) next[c.count + 1].push_back(std::move(inside));
    }
    part.by_count.clear();
    for (auto& [count, sources] : next) {
      CountPieces c{count, {}};
      if (sources.size() == 1) {
        c.pieces = std::move(sources.front());
      } else {
        // Pieces of one count that two counts' splits left side by side share edges.
        clipper::PolygonSet2 all;
        for (clipper::PolygonSet2& s : sources) {
          for (clipper::PolygonWithHoles2& p : s) all.push_back(std::move(p));
        }
        c.pieces = clipper::merge_adjacent(all);
      }
      if (!c.pieces.empty()) part.by_count.push_back(std::move(c));
    }
  }
}

std::vector<SunHoursRegion> FaceSunHours::regions(int step_min) const {
  std::map<std::size_t, std::vector<LitPolygon>> by_count;
  for (const Part& part : parts_) {
    for (const CountPieces& c : part.by_count) {
      std::vector<LitPolygon>& out = by_count[c.count];
      for (const clipper::PolygonWithHoles2& piece : c.pieces) {
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
      paths.push_back(std::move(path));
    }
    paths[at->second].instants.push_back(l);
  }
  return paths;
}

}  // namespace shadowgen
