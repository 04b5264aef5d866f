#include "shadowgen/shadows/sun_hours.h"

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/merge.h"
#include "clipper/normalize.h"
#include "detail/chart_region.h"
#include "hsr/area.h"
#include "hsr/spatial_grid.h"

namespace shadowgen {

FaceSunHours::FaceSunHours(const Face& face) {
  for (std::size_t k = 0; k < face.parts.size(); ++k) {
    // The part's own vertices are lifted back to themselves exactly; lit polygons are
    // charted exactly but not remembered (the part's plane places their vertices).
    std::optional<hsr::OwnChart> own = hsr::own_chart(face.parts[k]);
    if (!own) continue;
    Part part{k, face.parts[k], std::move(own->chart), clipper::normalized({own->flat}), {}};
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
    split_one_up(part, shadows::detail::ChartRegion(part.whole, std::move(clips)));
  }
}

void FaceSunHours::split_one_up(Part& part, const shadows::detail::ChartRegion& region) {
  // One split per count (detail/chart_region.h): over a sun path most pieces are far from
  // an instant's shadow edges, so the work per instant follows those edges.
  std::vector<CountPieces> next;
  const auto to = [&next](std::size_t count) -> clipper::PolygonSet2& {
    if (next.empty() || next.back().count != count) next.push_back({count, {}});
    return next.back().pieces;
  };
  clipper::PolygonSet2 carried;  // pieces of the count below that went one up
  for (std::size_t i = 0; i < part.by_count.size(); ++i) {
    CountPieces& c = part.by_count[i];
    clipper::PolygonSet2 stay = std::move(carried), up;
    carried.clear();
    region.split(std::move(c.pieces), stay, up);
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

void FaceSunHours::absorb(const FaceSunHours& later) {
  auto other = later.parts_.begin();
  for (Part& part : parts_) {
    while (other != later.parts_.end() && other->index < part.index) ++other;
    if (other == later.parts_.end()) break;
    if (other->index != part.index) continue;  // lit at none of later's instants
    const std::vector<CountPieces>& classes = other->by_count;
    if (classes.size() == 1) {  // one count over the whole part: every piece goes up by it
      for (CountPieces& c : part.by_count) c.count += classes[0].count;
      continue;
    }
    // later's pieces tile the part, each with its count. A piece here whose box meets the
    // boxes of later's pieces of one count alone lies in that count's region (every point
    // of it is in some piece of later's, whose box holds the point); the others are split
    // by the few pieces of later's that their boxes meet, one count after another, and
    // what is left takes the last count (the count 0 where it is one of them), slivers
    // that rounding left between later's pieces included.
    struct Later {
      const clipper::PolygonWithHoles2* piece;
      std::size_t count_index;
      clipper::Box2 box;
    };
    std::vector<Later> pieces;
    clipper::Box2 extent;
    for (std::size_t i = 0; i < classes.size(); ++i) {
      for (const clipper::PolygonWithHoles2& piece : classes[i].pieces) {
        pieces.push_back({&piece, i, clipper::box_of(piece)});
        extent.add(pieces.back().box);
      }
    }
    hsr::SpatialGrid grid(extent, pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) grid.insert(k, pieces[k].box);

    std::vector<CountPieces> done;  // one entry per piece or run of pieces, counts unsorted
    const auto put = [&done](std::size_t count, clipper::PolygonWithHoles2 piece) {
      if (done.empty() || done.back().count != count) done.push_back({count, {}});
      done.back().pieces.push_back(std::move(piece));
    };
    std::vector<std::size_t> near;
    for (CountPieces& c : part.by_count) {
      for (clipper::PolygonWithHoles2& piece : c.pieces) {
        const clipper::Box2 box = clipper::box_of(piece);
        near.clear();
        grid.query(box, near);
        std::erase_if(near, [&](std::size_t k) { return !pieces[k].box.overlaps(box); });
        std::sort(near.begin(), near.end());  // by count, then as later holds them
        if (near.empty() || pieces[near.front()].count_index == pieces[near.back()].count_index) {
          // One count around it (none: a sliver beside later's pieces, which counts none).
          put(c.count + (near.empty() ? 0 : classes[pieces[near.front()].count_index].count),
              std::move(piece));
          continue;
        }
        const std::size_t lowest = pieces[near.front()].count_index;
        const std::size_t rest =
            classes[lowest].count == 0 ? lowest : pieces[near.back()].count_index;
        clipper::PolygonSet2 left = {std::move(piece)};
        for (std::size_t from = 0; from < near.size() && !left.empty();) {
          const std::size_t count_index = pieces[near[from]].count_index;
          clipper::PolygonSet2 region;
          for (; from < near.size() && pieces[near[from]].count_index == count_index; ++from) {
            region.push_back(*pieces[near[from]].piece);
          }
          if (count_index == rest) continue;
          clipper::ClipResult r = clipper::clip(left, region);
          for (auto& p : r.inside) put(c.count + classes[count_index].count, std::move(p));
          left = std::move(r.outside);
        }
        for (auto& p : left) put(c.count + classes[rest].count, std::move(p));
      }
    }
    // Back to one entry per count, in increasing counts; pieces in the order they came.
    std::stable_sort(done.begin(), done.end(),
                     [](const CountPieces& a, const CountPieces& b) { return a.count < b.count; });
    part.by_count.clear();
    for (CountPieces& c : done) {
      if (!part.by_count.empty() && part.by_count.back().count == c.count) {
        clipper::PolygonSet2& out = part.by_count.back().pieces;
        for (auto& p : c.pieces) out.push_back(std::move(p));
      } else {
        part.by_count.push_back(std::move(c));
      }
    }
  }
}

SunHoursPieces FaceSunHours::pieces() const {
  SunHoursPieces result;
  for (const Part& part : parts_) {
    SunHoursPieces::Part out{part.index, {}};
    for (const CountPieces& c : part.by_count) out.counts.push_back({c.count, c.pieces});
    result.parts.push_back(std::move(out));
  }
  return result;
}

FaceSunHours::FaceSunHours(const Face& face, const SunHoursPieces& pieces) : FaceSunHours(face) {
  const auto fail = [&face](const std::string& what) {
    throw std::invalid_argument("face '" + face.id + "': sun-hours pieces: " + what);
  };
  if (pieces.parts.size() != parts_.size()) {
    fail(std::to_string(pieces.parts.size()) + " parts, the face has " +
         std::to_string(parts_.size()) + " with area");
  }
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const SunHoursPieces::Part& given = pieces.parts[k];
    if (given.part != parts_[k].index) {
      fail("part " + std::to_string(given.part) + " where part " + std::to_string(parts_[k].index) +
           " was expected");
    }
    if (given.counts.empty()) fail("part " + std::to_string(given.part) + " has no pieces");
    std::vector<CountPieces> by_count;
    for (const SunHoursPieces::Count& c : given.counts) {
      if (!by_count.empty() && c.count <= by_count.back().count) fail("counts not increasing");
      if (c.pieces.empty()) fail("a count with no pieces");
      for (const clipper::PolygonWithHoles2& piece : c.pieces) {
        const auto check = [&fail](const clipper::Loop2& loop) {
          if (loop.size() < 3) fail("a loop of fewer than three vertices");
          for (const clipper::Point2& p : loop) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail("a coordinate not finite");
          }
        };
        check(piece.outer);
        for (const clipper::Loop2& hole : piece.holes) check(hole);
      }
      by_count.push_back({c.count, c.pieces});
    }
    parts_[k].by_count = std::move(by_count);
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
  const auto path_of = [](const std::string& id, int step_min, const std::string& from,
                          const std::string& to) {
    SunPathHours path;
    path.id = id;
    path.step_min = step_min;
    path.from = from;
    path.to = to;
    return path;
  };
  std::vector<SunPathHours> paths;
  std::map<std::string, std::size_t> index;
  for (const SunPathSpan& span : scene.sun_paths) {
    index.emplace(span.id, paths.size());
    paths.push_back(path_of(span.id, span.step_min, span.from, span.to));
  }
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const std::optional<SunInstant>& sun = scene.lights[l].sun;
    if (!sun || sun->step_min <= 0) continue;
    const auto [at, added] = index.emplace(sun->sun_id, paths.size());
    if (added) paths.push_back(path_of(sun->sun_id, sun->step_min, sun->path_from, sun->path_to));
    paths[at->second].instants.push_back(l);
  }
  return paths;
}

}  // namespace shadowgen
