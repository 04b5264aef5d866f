// Closed solids found among the parts (every edge run as often one way as the other,
// bounding their insides outward, touching themselves nowhere: touches_itself.h), and
// which of their parts need not occlude for a light.

#include "closed_solids.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numeric>
#include <optional>
#include <span>
#include <utility>

#include "clipper/predicates.h"
#include "hsr/chart_triangles.h"
#include "hsr/parallel.h"
#include "touches_itself.h"

namespace shadowgen::shadows::detail {
namespace {

constexpr double kUnit = 0x1p-53;

// A part's triangles on its own corners, each running as its outer loop does (so its
// front side is the part's, by the right-hand rule); nothing where it does not split.
std::optional<std::vector<hsr::Triangle3>> triangles_of(const hsr::Polygon3& polygon,
                                                        const hsr::Plane3& plane) {
  if (polygon.outer.size() == 3 && polygon.holes.empty()) {
    return std::vector<hsr::Triangle3>{{polygon.outer[0], polygon.outer[1], polygon.outer[2]}};
  }
  const std::optional<hsr::ChartTriangles> split = hsr::chart_triangles(polygon, plane.normal);
  if (!split) return std::nullopt;
  std::vector<hsr::Triangle3> out;
  out.reserve(split->triangles.size());
  for (const clipper::Triangle& t : split->triangles) {
    out.push_back({split->corners[t[0]], split->corners[t[1]], split->corners[t[2]]});
  }
  return out;
}

// A corner's exact coordinates as a key (0 and -0 alike), ordered lexicographically.
using CornerKey = std::array<double, 3>;
CornerKey key_of(const glm::dvec3& p) { return {p.x + 0.0, p.y + 0.0, p.z + 0.0}; }

// One edge of a loop or triangle, by its lower and higher corner, with the way it runs.
// Edges are told apart by their corners' exact coordinates, so runs need no shared
// numbering of the corners and are made for every part at once.
struct EdgeRun {
  CornerKey low, high;
  std::uint32_t part;
  bool up;  // from low to high
};

// The edges of the closed loop `loop` (repeated corners in a row add none), written from
// `out` on; returns the end of what was written.
EdgeRun* add_runs(EdgeRun* out, std::span<const glm::dvec3> loop, std::size_t part) {
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const CornerKey from = key_of(loop[k]), to = key_of(loop[k + 1 == loop.size() ? 0 : k + 1]);
    if (from == to) continue;
    const bool up = from < to;
    *out++ = {up ? from : to, up ? to : from, static_cast<std::uint32_t>(part), up};
  }
  return out;
}

// The runs of the closed loop `loop`'s edges, added to `runs`.
void add_runs(std::vector<EdgeRun>& runs, std::span<const glm::dvec3> loop, std::size_t part) {
  const std::size_t first = runs.size();
  runs.resize(first + loop.size());
  const EdgeRun* end = add_runs(runs.data() + first, loop, part);
  runs.resize(static_cast<std::size_t>(end - runs.data()));
}

bool same_edge(const EdgeRun& a, const EdgeRun& b) { return a.low == b.low && a.high == b.high; }

// In edge order; the runs of one edge in any order (nothing asked of them depends on it).
void sort_runs(std::vector<EdgeRun>& runs) {
  tbb::parallel_sort(runs.begin(), runs.end(), [](const EdgeRun& a, const EdgeRun& b) {
    return a.low != b.low ? a.low < b.low : a.high < b.high;
  });
}

// Calls visit(uses) with the runs of each edge, runs sorted by sort_runs.
template <typename Visit>
void for_each_edge(const std::vector<EdgeRun>& runs, Visit visit) {
  for (std::size_t g = 0, e = 0; g < runs.size(); g = e) {
    for (e = g + 1; e < runs.size() && same_edge(runs[e], runs[g]); ++e) {
    }
    visit(std::span<const EdgeRun>(runs.data() + g, e - g));
  }
}

// One surface through the edge, its two sides run opposite ways: the edge of a closed,
// consistently oriented surface.
bool once_each_way(std::span<const EdgeRun> uses) {
  return uses.size() == 2 && uses[0].up != uses[1].up;
}

// Every part's boundary runs, made in parallel: the runs of part i from offset[i] on.
std::vector<EdgeRun> boundary_runs(const FaceParts& parts) {
  const std::size_t n = parts.size();
  std::vector<std::size_t> offset(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t corners = parts.polygons[i].outer.size();
    for (const hsr::Loop3& hole : parts.polygons[i].holes) corners += hole.size();
    offset[i + 1] = offset[i] + corners;
  }
  std::vector<EdgeRun> runs(offset[n]);
  std::vector<std::size_t> made(n);
  hsr::for_each_in_parallel(n, [&](std::size_t i) {
    const hsr::Polygon3& polygon = parts.polygons[i];
    EdgeRun* end = add_runs(runs.data() + offset[i], polygon.outer, i);
    for (const hsr::Loop3& hole : polygon.holes) end = add_runs(end, hole, i);
    made[i] = static_cast<std::size_t>(end - (runs.data() + offset[i]));
  });
  // Closed up where repeated corners left gaps.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (kept != offset[i]) {
      std::copy_n(runs.begin() + static_cast<std::ptrdiff_t>(offset[i]), made[i],
                  runs.begin() + static_cast<std::ptrdiff_t>(kept));
    }
    kept += made[i];
  }
  runs.resize(kept);
  return runs;
}

double norm1(const glm::dvec3& v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

// Whether the closed surface of the triangles bounds its inside outward: its volume,
// summed from the first corner, positive beyond the sum's rounding (each product within
// 8u of its terms' magnitudes, the additions within u·n of the terms, and the corners'
// shift within u of each, which moves the volume by at most u·R per unit of area).
bool outward(const std::vector<hsr::Triangle3>& triangles) {
  const glm::dvec3 o = triangles.front()[0];
  double volume = 0.0, magnitude = 0.0, terms = 0.0, area = 0.0, reach = 0.0;
  for (const hsr::Triangle3& t : triangles) {
    const glm::dvec3 a = t[0] - o, b = t[1] - o, c = t[2] - o;
    const double term = glm::dot(a, glm::cross(b, c));
    volume += term;
    terms += std::fabs(term);
    magnitude += norm1(a) * norm1(b) * norm1(c);
    area += norm1(b - a) * norm1(c - a);
    reach = std::max({reach, norm1(a), norm1(b), norm1(c)});
  }
  const double n = static_cast<double>(triangles.size());
  const double bound =
      8.0 * kUnit * magnitude + 2.0 * n * kUnit * terms + 8.0 * kUnit * reach * area;
  return volume > bound;
}

// Whether the light travelling along `direction` reaches the triangle's back side, by more
// than the rounding of its normal's product with the direction (each within 16u of its
// terms' magnitudes, generously).
bool turned_away(const hsr::Triangle3& t, const glm::dvec3& direction) {
  const glm::dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  const double along = glm::dot(glm::cross(e1, e2), direction);
  return along > 32.0 * kUnit * norm1(e1) * norm1(e2) * norm1(direction);
}

}  // namespace

ClosedSolids::ClosedSolids(const FaceParts& parts) : solid_of_part_(parts.size(), -1) {
  const std::size_t n = parts.size();
  // The parts' boundaries first, which need no triangles: parts are joined along the
  // edges they share, and only components whose every edge runs once each way are
  // triangulated and looked at further.
  std::vector<EdgeRun> runs = boundary_runs(parts);
  sort_runs(runs);
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto root = [&parent](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for_each_edge(runs, [&](std::span<const EdgeRun> uses) {
    for (const EdgeRun& use : uses.subspan(1)) parent[root(use.part)] = root(uses[0].part);
  });
  std::vector<char> closed(n, 1);
  for_each_edge(runs, [&](std::span<const EdgeRun> uses) {
    if (!once_each_way(uses)) closed[root(uses[0].part)] = 0;
  });
  runs = {};
  // The closed components, each listed in part order, in the order of their first parts.
  std::vector<std::vector<std::size_t>> members;
  {
    std::vector<std::size_t> component(n, n);  // by root: its index in `members`
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t r = root(i);
      if (!closed[r]) continue;
      if (component[r] == n) {
        component[r] = members.size();
        members.emplace_back();
      }
      members[component[r]].push_back(i);
    }
  }
  part_triangles_.resize(n);
  // Each component on its own, in parallel: it writes only its own parts' triangles.
  std::vector<std::optional<Solid>> found(members.size());
  hsr::for_each_in_parallel(members.size(), [&](std::size_t c) {
    const std::vector<std::size_t>& list = members[c];
    // Triangulated, the surface must still run through each edge once each way: a
    // diagonal of one part along which others meet is an edge of four triangles.
    Solid solid;
    // A component of triangles alone has its parts' boundaries for its triangles' edges.
    const bool all_triangles = std::all_of(list.begin(), list.end(), [&](std::size_t i) {
      return parts.polygons[i].outer.size() == 3 && parts.polygons[i].holes.empty();
    });
    std::vector<EdgeRun> triangle_runs;
    std::vector<int> planes;  // per triangle, its part's coplanar group (exactly one plane)
    bool split = true;
    for (const std::size_t i : list) {
      std::optional<std::vector<hsr::Triangle3>> triangles =
          triangles_of(parts.polygons[i], parts.planes[i]);
      if (!triangles || triangles->empty()) {
        split = false;
        break;
      }
      for (const hsr::Triangle3& t : *triangles) {
        if (!all_triangles) add_runs(triangle_runs, std::span<const glm::dvec3>(t.data(), 3), i);
      }
      solid.triangles.insert(solid.triangles.end(), triangles->begin(), triangles->end());
      planes.insert(planes.end(), triangles->size(), parts.coplanar[i]);
      part_triangles_[i] = std::move(*triangles);
    }
    bool manifold = split;
    if (manifold && !all_triangles) {
      sort_runs(triangle_runs);
      for_each_edge(triangle_runs, [&](std::span<const EdgeRun> uses) {
        manifold = manifold && once_each_way(uses);
      });
    }
    if (!manifold || !outward(solid.triangles) || touches_itself(solid.triangles, planes)) {
      for (const std::size_t i : list) part_triangles_[i].clear();
      return;
    }
    solid.low = solid.high = solid.triangles.front()[0];
    for (const hsr::Triangle3& t : solid.triangles) {
      solid.low = glm::min(solid.low, glm::min(glm::min(t[0], t[1]), t[2]));
      solid.high = glm::max(solid.high, glm::max(glm::max(t[0], t[1]), t[2]));
    }
    // Triangles without area cross no ray: what each light asks of the solid leaves them
    // out once here.
    std::erase_if(solid.triangles, hsr::degenerate);
    for (const std::size_t i : list) std::erase_if(part_triangles_[i], hsr::degenerate);
    found[c] = std::move(solid);
  });
  for (std::size_t c = 0; c < members.size(); ++c) {
    if (!found[c]) continue;
    const int index = static_cast<int>(solids_.size());
    solids_.push_back(std::move(*found[c]));
    for (const std::size_t i : members[c]) solid_of_part_[i] = index;
  }
}

bool ClosedSolids::outside(const Solid& solid, const glm::dvec3& point) const {
  // The winding number at the point, from a segment to a point beyond the solid's box
  // (winding number 0): each crossing of a triangle's inside counts +1 where the point
  // lies behind the triangle (the segment leaves the inside there) and -1 where it lies
  // in front, decided exactly (orient3d). A segment through a side or a corner, or with
  // its far end in a triangle's plane, is tried again in another direction; a point on
  // the surface is not outside.
  static constexpr std::array<glm::dvec3, 4> kDirections = {
      glm::dvec3{0.5773502691896258, 0.40138073020291836, 0.7110521567287463},
      glm::dvec3{-0.31214525826373946, 0.8812935391281427, 0.35469577062918415},
      glm::dvec3{0.7019236545393874, -0.22132054316468426, -0.6770935823917463},
      glm::dvec3{-0.6133125680521226, -0.5263316488112826, 0.5890411449640826}};
  const glm::dvec3 size = solid.high - solid.low;
  const double far = 4.0 * (norm1(size) + norm1(point - solid.low) + 1.0);
  for (const glm::dvec3& direction : kDirections) {
    const glm::dvec3 end = point + far * direction;
    int winding = 0;
    bool clear = true;
    for (const hsr::Triangle3& t : solid.triangles) {
      const int s1 = static_cast<int>(clipper::orient3d(t[0], t[1], t[2], point));
      const int s2 = static_cast<int>(clipper::orient3d(t[0], t[1], t[2], end));
      if (s1 == 0) {
        if (hsr::segment_meets_triangle(point, point, t)) return false;  // on the surface
        continue;  // in the triangle's plane, beside it: the segment leaves the plane there
      }
      if (s1 * s2 > 0) continue;
      if (s2 == 0) {
        clear = false;  // the far end in a plane: not expected, try another way
        break;
      }
      const int o1 = static_cast<int>(clipper::orient3d(point, end, t[0], t[1]));
      const int o2 = static_cast<int>(clipper::orient3d(point, end, t[1], t[2]));
      const int o3 = static_cast<int>(clipper::orient3d(point, end, t[2], t[0]));
      if ((o1 > 0 && o2 > 0 && o3 > 0) || (o1 < 0 && o2 < 0 && o3 < 0)) {
        // Through the inside. orient3d > 0: the point lies behind the triangle, on the
        // inner side of an outward surface.
        winding += s1 > 0 ? 1 : -1;
      } else if ((o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0)) {
        clear = false;  // through a side or a corner
        break;
      }
    }
    if (clear) return winding == 0;
  }
  return false;
}

std::vector<char> ClosedSolids::need_not_occlude(const Light& light) const {
  std::vector<char> out(solid_of_part_.size(), 0);
  if (solids_.empty()) return out;
  std::vector<char> light_outside(solids_.size(), 1);
  if (light.type == LightType::kPoint) {
    for (std::size_t s = 0; s < solids_.size(); ++s) {
      light_outside[s] = outside(solids_[s], light.position) ? 1 : 0;
    }
  }
  for (std::size_t i = 0; i < solid_of_part_.size(); ++i) {
    const int s = solid_of_part_[i];
    if (s < 0 || !light_outside[static_cast<std::size_t>(s)]) continue;
    bool away = true;
    for (const hsr::Triangle3& t : part_triangles_[i]) {
      away = light.type == LightType::kDirectional
                 ? turned_away(t, light.direction)
                 : clipper::orient3d(t[0], t[1], t[2], light.position) ==
                       clipper::Orientation::kCounterClockwise;
      if (!away) break;
    }
    out[i] = away ? 1 : 0;
  }
  return out;
}

}  // namespace shadowgen::shadows::detail
