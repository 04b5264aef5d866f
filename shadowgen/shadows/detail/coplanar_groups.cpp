#include "coplanar_groups.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numeric>

#include "clipper/predicates.h"
#include "hsr/parallel.h"
#include "hsr/vector_length.h"

namespace shadowgen::shadows::detail {
namespace {

// Plane orientation does not matter for coplanarity: flip so the largest component of
// the normal is positive.
hsr::Plane3 canonical(const hsr::Plane3& p) {
  const glm::dvec3 a = glm::abs(p.normal);
  const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  if (p.normal[k] >= 0.0) return p;
  return {-p.normal, -p.offset};
}

// Three vertices of the outer loop spanning its plane as widely as the loop allows.
bool spanning_triple(const hsr::Loop3& loop, glm::dvec3 out[3]) {
  if (loop.size() < 3) return false;
  out[0] = loop[0];
  std::size_t far = 1;
  for (std::size_t i = 1; i < loop.size(); ++i) {
    if (glm::distance(loop[i], loop[0]) > glm::distance(loop[far], loop[0])) far = i;
  }
  out[1] = loop[far];
  std::size_t best = 0;
  double best_area = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const double a = hsr::stable_length(glm::cross(out[1] - out[0], loop[i] - out[0]));
    if (a > best_area) {
      best_area = a;
      best = i;
    }
  }
  out[2] = loop[best];
  return best_area > 0.0;
}

bool exactly_on_plane(const hsr::Polygon3& p, const glm::dvec3 t[3]) {
  auto on = [&t](const hsr::Loop3& loop) {
    return std::all_of(loop.begin(), loop.end(), [&t](const glm::dvec3& v) {
      return clipper::orient3d(t[0], t[1], t[2], v) == clipper::Orientation::kCollinear;
    });
  };
  if (!on(p.outer)) return false;
  return std::all_of(p.holes.begin(), p.holes.end(), on);
}

}  // namespace

std::vector<int> coplanar_groups(std::span<const hsr::Polygon3> polygons,
                                 std::span<const hsr::Plane3> planes) {
  const std::size_t n = polygons.size();
  std::vector<int> group(n, -1);
  std::vector<hsr::Plane3> canon(n);
  std::vector<double> magnitude(n, 0.0);  // of each polygon's offset and coordinates
  hsr::for_each_in_parallel(n, [&](std::size_t i) {
    canon[i] = canonical(planes[i]);
    double m = std::fabs(canon[i].offset);
    for (const glm::dvec3& v : polygons[i].outer) {
      m = std::max({m, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    }
    magnitude[i] = m;
  });
  double scale = 0.0;
  for (const double m : magnitude) scale = std::max(scale, m);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return canon[a].offset < canon[b].offset; });
  // Fitted planes of exactly coplanar polygons differ only by rounding: a generous window
  // finds every candidate, the exact test decides.
  const double window = 1e-9 * std::max(scale, 1e-300);
  // Where consecutive offsets lie more than the window apart, no polygon after the gap can
  // join a group before it: the runs between such gaps are settled independently, in
  // parallel, each numbering its groups from 0 in its own order; the numbers are then
  // shifted by the groups of the runs before, which gives the numbering of one pass.
  std::vector<std::size_t> runs{0};
  for (std::size_t t = 1; t < n; ++t) {
    if (canon[order[t]].offset - canon[order[t - 1]].offset > window) runs.push_back(t);
  }
  runs.push_back(n);
  std::vector<int> groups_in_run(runs.size() - 1, 0);
  hsr::for_each_in_parallel(runs.size() - 1, [&](std::size_t run) {
    struct Representative {
      std::size_t polygon;
      glm::dvec3 triple[3];
      int id;
    };
    std::vector<Representative> reps;
    std::size_t first_rep = 0;
    int next_id = 0;
    for (std::size_t t = runs[run]; t < runs[run + 1]; ++t) {
      const std::size_t i = order[t];
      if (glm::length(planes[i].normal) == 0.0) continue;  // no area: no plane
      while (first_rep < reps.size() &&
             canon[i].offset - canon[reps[first_rep].polygon].offset > window) {
        ++first_rep;
      }
      bool placed = false;
      for (std::size_t r = first_rep; r < reps.size() && !placed; ++r) {
        const Representative& rep = reps[r];
        if (glm::dot(canon[i].normal, canon[rep.polygon].normal) < 1.0 - 1e-9) continue;
        if (!exactly_on_plane(polygons[i], rep.triple)) continue;
        group[i] = rep.id;
        group[rep.polygon] = rep.id;
        placed = true;
      }
      if (placed) continue;
      Representative rep{i, {}, next_id};
      if (!spanning_triple(polygons[i].outer, rep.triple)) continue;
      ++next_id;
      reps.push_back(rep);
    }
    groups_in_run[run] = next_id;
  });
  int shift = 0;
  for (std::size_t run = 0; run + 1 < runs.size(); ++run) {
    if (shift != 0) {
      for (std::size_t t = runs[run]; t < runs[run + 1]; ++t) {
        if (group[order[t]] >= 0) group[order[t]] += shift;
      }
    }
    shift += groups_in_run[run];
  }
  return group;
}

}  // namespace shadowgen::shadows::detail
