#include "detail/lit_checks.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <sstream>

#include "clipper/clip.h"
#include "hsr/area.h"
#include "hsr/collinearity.h"
#include "hsr/perimeter.h"
#include "numbers.h"

namespace shadowgen::scene::detail {
namespace {

double rounding_area_bound(const clipper::PolygonWithHoles2& polygon) {
  double sum = clipper::rounding_area_bound(polygon.outer);
  for (const clipper::Loop2& hole : polygon.holes) sum += clipper::rounding_area_bound(hole);
  return sum;
}

bool same_loop(const hsr::Loop3& a, const hsr::Loop3& b) {
  if (a.size() != b.size()) return false;
  const std::size_t n = a.size();
  for (std::size_t start = 0; start < n; ++start) {
    bool equal = true;
    for (std::size_t i = 0; i < n && equal; ++i) equal = a[i] == b[(start + i) % n];
    if (equal) return true;
  }
  return n == 0;
}

// The same polygon: the same loops, each possibly starting at another vertex.
bool same_polygon(const hsr::Polygon3& a, const hsr::Polygon3& b) {
  if (a.holes.size() != b.holes.size() || !same_loop(a.outer, b.outer)) return false;
  for (std::size_t k = 0; k < a.holes.size(); ++k) {
    if (!same_loop(a.holes[k], b.holes[k])) return false;
  }
  return true;
}

std::optional<std::string> loop_size_problem(const hsr::Polygon3& polygon) {
  auto problem = [](const std::string& name, std::size_t size) {
    return name + " has " + std::to_string(size) + " vertices; at least 3 are needed";
  };
  if (polygon.outer.size() < 3) return problem("the outer loop", polygon.outer.size());
  for (std::size_t k = 0; k < polygon.holes.size(); ++k) {
    if (polygon.holes[k].size() < 3) {
      return problem("hole " + std::to_string(k), polygon.holes[k].size());
    }
  }
  return std::nullopt;
}

}  // namespace

LitChecker::LitChecker(const Face& face) : several_parts_(face.parts.size() > 1) {
  face_area_ = hsr::area(face.parts);
  parts_.reserve(face.parts.size());
  for (const hsr::Polygon3& polygon : face.parts) {
    Part part;
    part.polygon = &polygon;
    part.origin = polygon.outer.front();
    glm::dvec3 lo = part.origin;
    glm::dvec3 hi = part.origin;
    for (const glm::dvec3& p : polygon.outer) {
      part.centroid += p - part.origin;
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    part.centroid /= static_cast<double>(polygon.outer.size());
    const glm::dvec3 size = hi - lo;
    const glm::dvec3 magnitude = glm::max(glm::abs(lo), glm::abs(hi));
    part.extent = std::max({size.x, size.y, size.z});
    part.lo = lo;
    part.hi = hi;
    part.reach = kRoundingReach * (part.extent + std::max({magnitude.x, magnitude.y, magnitude.z}));
    part.vertex_reach = 2.0 * face.vertex_rounding;
    part.perimeter = hsr::perimeter(polygon);
    const double area = hsr::area(polygon);
    part.tilt_reach =
        area > 0.0 ? kRoundingReach * part.extent * part.extent * part.extent / (2.0 * area) : 0.0;
    part.normal = hsr::plane_of(polygon).normal;
    part.flat =
        finite(part.normal) && part.normal != glm::dvec3(0.0) && !hsr::all_collinear(polygon.outer);
    if (part.flat) {
      part.chart = hsr::chart_facing(part.normal);
      part.flat_polygon = to_chart(part, polygon);
    }
    parts_.push_back(std::move(part));
  }
}

double LitChecker::distance_to_plane(const Part& part, const glm::dvec3& p) const {
  return std::abs(glm::dot(part.normal, (p - part.origin) - part.centroid));
}

clipper::PolygonWithHoles2 LitChecker::to_chart(const Part& part,
                                                const hsr::Polygon3& polygon) const {
  auto flatten = [&](const hsr::Loop3& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) out.push_back(part.chart(p - part.origin));
    return out;
  };
  clipper::PolygonWithHoles2 out{flatten(polygon.outer), {}};
  for (const hsr::Loop3& hole : polygon.holes) out.holes.push_back(flatten(hole));
  return out;
}

std::size_t LitChecker::nearest_part(const hsr::Polygon3& polygon) const {
  std::size_t best = 0;
  double best_distance = INFINITY;
  std::vector<double> distances(parts_.size(), 0.0);
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    double& d = distances[k];
    for (const glm::dvec3& p : polygon.outer) d = std::max(d, distance_to_plane(parts_[k], p));
    if (d < best_distance) {
      best_distance = d;
      best = k;
    }
  }
  for (std::size_t k = 0; k < parts_.size(); ++k) {
    const Part& part = parts_[k];
    if (!(distances[k] <= best_distance + part.reach)) continue;
    const bool held =
        std::all_of(polygon.outer.begin(), polygon.outer.end(), [&](const glm::dvec3& p) {
          return glm::all(glm::greaterThanEqual(p, part.lo - part.reach)) &&
                 glm::all(glm::lessThanEqual(p, part.hi + part.reach));
        });
    if (held) return k;
  }
  return best;
}

std::optional<LitProblem> LitChecker::check(std::span<const LitPolygon> lit) const {
  if (std::optional<LitProblem> problem = check_loops_and_planes(lit)) return problem;
  if (std::optional<LitProblem> problem = check_area(lit)) return problem;
  for (std::size_t part = 0; part < parts_.size(); ++part) {
    if (std::optional<LitProblem> problem = check_inside(lit, part)) return problem;
  }
  return std::nullopt;
}

std::optional<LitProblem> LitChecker::check_loops_and_planes(
    std::span<const LitPolygon> lit) const {
  for (std::size_t k = 0; k < lit.size(); ++k) {
    if (std::optional<std::string> problem = loop_size_problem(lit[k].polygon)) {
      return LitProblem{k, *problem};
    }
    if (lit[k].part >= parts_.size()) {
      return LitProblem{k, "lies on part " + std::to_string(lit[k].part) + ", but the face has " +
                               std::to_string(parts_.size())};
    }
    const Part& part = parts_[lit[k].part];
    if (!part.flat) continue;
    const double tolerance =
        kPlanarityTolerance * part.extent + part.reach + part.tilt_reach + part.vertex_reach;
    double worst = 0.0;
    auto visit = [&](const hsr::Loop3& loop) {
      for (const glm::dvec3& p : loop) worst = std::max(worst, distance_to_plane(part, p));
    };
    visit(lit[k].polygon.outer);
    for (const hsr::Loop3& hole : lit[k].polygon.holes) visit(hole);
    if (!(worst <= tolerance)) {
      const std::string plane =
          several_parts_ ? "the plane of part " + std::to_string(lit[k].part) + " of its face"
                         : "its face's plane";
      return LitProblem{k, "lies off " + plane + ": a vertex is " + short_number(worst, 6) +
                               " from it (tolerance " + short_number(tolerance, 6) + ")"};
    }
  }
  return std::nullopt;
}

double LitChecker::area_tolerance(std::span<const LitPolygon> lit) const {
  double tolerance = 0.0;
  for (const Part& part : parts_) tolerance += part.reach * part.perimeter;
  for (const LitPolygon& p : lit) tolerance += parts_[p.part].reach * hsr::perimeter(p.polygon);
  return tolerance;
}

std::optional<LitProblem> LitChecker::check_area(std::span<const LitPolygon> lit) const {
  double lit_area = 0.0;
  for (const LitPolygon& p : lit) lit_area += hsr::area(p.polygon);
  const double tolerance = area_tolerance(lit);
  if (!std::isfinite(lit_area)) {
    return LitProblem{std::nullopt, "the lit area is not a finite number"};
  }
  if (lit_area > face_area_ + tolerance) {
    std::string what = "the lit polygons cover an area of " + short_number(lit_area, 6) +
                       ", more than the face's area of " + short_number(face_area_, 6);
    if (face_area_ > 0.0)
      what += " (a lit fraction of " + short_number(lit_area / face_area_, 6) + ")";
    return LitProblem{std::nullopt, what};
  }
  return std::nullopt;
}

std::optional<LitProblem> LitChecker::check_inside(std::span<const LitPolygon> lit,
                                                   std::size_t part_index) const {
  const Part& part = parts_[part_index];
  std::vector<std::size_t> on_part;
  for (std::size_t k = 0; k < lit.size(); ++k) {
    if (lit[k].part == part_index) on_part.push_back(k);
  }
  if (on_part.empty() || !part.flat) return std::nullopt;
  // The common case of a face lit whole: its one lit polygon is the part itself.
  if (on_part.size() == 1 && same_polygon(lit[on_part[0]].polygon, *part.polygon)) {
    return std::nullopt;
  }
  std::vector<clipper::PolygonWithHoles2> clips;
  clips.reserve(on_part.size());
  double lit_sum = 0.0;
  double tolerance = part.reach * part.perimeter + rounding_area_bound(part.flat_polygon);
  for (const std::size_t k : on_part) {
    clips.push_back(to_chart(part, lit[k].polygon));
    lit_sum += clipper::area(clips.back());
    tolerance += part.reach * hsr::perimeter(lit[k].polygon) + rounding_area_bound(clips.back());
  }
  const double covered = clipper::area(clipper::clip(part.flat_polygon, clips).inside);
  if (lit_sum - covered <= tolerance) return std::nullopt;
  return diagnose_inside(lit, part_index, on_part, tolerance);
}

// Which lit polygon is to blame when, on one part, they cover less than their own area:
// one that reaches outside the part, one repeated, or else an overlap.
std::optional<LitProblem> LitChecker::diagnose_inside(std::span<const LitPolygon> lit,
                                                      std::size_t part_index,
                                                      const std::vector<std::size_t>& on_part,
                                                      double tolerance) const {
  const Part& part = parts_[part_index];
  // Chart areas are the part's areas scaled by the normal's dropped component.
  const double to_3d = 1.0 / std::abs(part.normal[part.chart.dropped_axis]);
  for (const std::size_t k : on_part) {
    const clipper::PolygonWithHoles2 flat = to_chart(part, lit[k].polygon);
    const double outside = clipper::area(clipper::clip(flat, part.flat_polygon).outside);
    const double own = part.reach * (part.perimeter + hsr::perimeter(lit[k].polygon)) +
                       rounding_area_bound(flat) + rounding_area_bound(part.flat_polygon);
    if (outside > own) {
      return LitProblem{k, "lies outside its face: an area of " + short_number(outside * to_3d, 6) +
                               " of its " + short_number(clipper::area(flat) * to_3d, 6) +
                               " is beyond the face's boundary"};
    }
  }
  for (std::size_t j = 0; j < on_part.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      if (same_polygon(lit[on_part[i]].polygon, lit[on_part[j]].polygon)) {
        return LitProblem{on_part[j],
                          "repeats lit polygon " + std::to_string(on_part[i]) + " of this light"};
      }
    }
  }
  return LitProblem{std::nullopt, "the lit polygons overlap (beyond rounding: " +
                                      short_number(tolerance * to_3d, 6) + " of area)"};
}

}  // namespace shadowgen::scene::detail
