#include "face_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>
#include <utility>

#include "clipper/predicates.h"
#include "hsr/collinearity.h"
#include "loop_validation.h"
#include "hsr/plane_chart.h"
#include "clipper/triangulate.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::detail {

namespace {

std::string short_number(double value) {
  std::ostringstream s;
  s.precision(3);
  s << value;
  return s.str();
}

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A chart for a loop whose Newell normal came out zero (its signed areas cancel, as in a
// figure-eight, or underflow): any chart in which it is not collinear; validation then
// finds what is wrong with it.
hsr::PlaneChart chart_without_normal(const hsr::Loop3& loop) {
  for (int axis : {2, 0, 1}) {
    const hsr::PlaneChart chart{axis};
    const clipper::Point2 a = chart(loop[0]);
    for (std::size_t i = 1; i < loop.size(); ++i) {
      const clipper::Point2 b = chart(loop[i]);
      if (b == a) continue;
      for (std::size_t j = i + 1; j < loop.size(); ++j) {
        if (clipper::orient2d(a, b, chart(loop[j])) != clipper::Orientation::kCollinear) {
          return chart;
        }
      }
      break;
    }
  }
  return {};
}

clipper::Loop2 to_chart(const hsr::Loop3& loop, const hsr::PlaneChart& chart) {
  clipper::Loop2 out;
  out.reserve(loop.size());
  for (const glm::dvec3& p : loop) out.push_back(chart(p));
  return out;
}

// Orthonormal coordinates on the plane through `origin` with unit normal n, oriented so
// that a loop counter-clockwise seen from the side n points to stays counter-clockwise.
// The coordinates are rounded (a construction, unlike a chart).
class PlaneFrame {
 public:
  PlaneFrame(const glm::dvec3& origin, const glm::dvec3& n) : origin_(origin) {
    const glm::dvec3 a = glm::abs(n);
    const glm::dvec3 axis = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
                            : a.y <= a.z             ? glm::dvec3(0, 1, 0)
                                                     : glm::dvec3(0, 0, 1);
    u_ = glm::normalize(glm::cross(n, axis));
    v_ = glm::cross(n, u_);
  }

  clipper::Loop2 project(const hsr::Loop3& loop) const {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) {
      const glm::dvec3 d = p - origin_;
      out.push_back({glm::dot(d, u_), glm::dot(d, v_)});
    }
    return out;
  }

 private:
  glm::dvec3 origin_, u_, v_;
};

struct Planarity {
  double deviation = 0.0;  // largest distance of a vertex from the best-fit plane
  double extent = 0.0;     // largest side of the bounding box
};

// Distances are taken relative to the outer loop's first vertex, so a face far from the
// origin is measured as precisely as one at it.
Planarity planarity(const hsr::Polygon3& polygon, const glm::dvec3& normal) {
  const glm::dvec3 o = polygon.outer[0];
  glm::dvec3 centroid(0.0);
  for (const glm::dvec3& p : polygon.outer) centroid += p - o;
  centroid /= static_cast<double>(polygon.outer.size());
  Planarity result;
  glm::dvec3 lo = o;
  glm::dvec3 hi = o;
  auto visit = [&](const hsr::Loop3& loop) {
    for (const glm::dvec3& p : loop) {
      result.deviation = std::max(result.deviation, std::abs(glm::dot(normal, (p - o) - centroid)));
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  };
  visit(polygon.outer);
  for (const hsr::Loop3& hole : polygon.holes) visit(hole);
  const glm::dvec3 size = hi - lo;
  result.extent = std::max({size.x, size.y, size.z});
  return result;
}

}  // namespace

std::string face_message(const std::string& file, const std::string& face_id,
                         const std::string& what) {
  return InputError(file, face_id, what).what();
}

Face build_face(hsr::Polygon3 polygon, const FaceSource& source, bool strict,
                std::vector<std::string>& warnings) {
  auto fail = [&](const std::string& what) { throw InputError(source.file, source.id, what); };
  auto warn = [&](const std::string& what) {
    warnings.push_back(face_message(source.file, source.id, what));
  };
  const bool mesh = source.kind == FaceKind::kMeshFace;
  const std::string outer_name = mesh ? "the face" : "the outer loop";
  Face face{source.id, {}, source.file};

  if (polygon.outer.size() < 3) {
    fail(outer_name + " has " + std::to_string(polygon.outer.size()) +
         " vertices; at least 3 are needed");
  }
  for (std::size_t k = 0; k < polygon.holes.size(); ++k) {
    if (polygon.holes[k].size() < 3) {
      fail("hole " + std::to_string(k) + " has " + std::to_string(polygon.holes[k].size()) +
           " vertices; at least 3 are needed");
    }
    if (hsr::distinct_points_up_to_3(polygon.holes[k]) < 3) {
      fail("hole " + std::to_string(k) + " has fewer than 3 distinct vertices");
    }
  }

  // Degenerate faces are kept as given.
  const bool too_few = hsr::distinct_points_up_to_3(polygon.outer) < 3;
  if (too_few && !mesh) fail(outer_name + " has fewer than 3 distinct vertices");
  if (too_few || hsr::all_collinear(polygon.outer)) {
    if (!polygon.holes.empty()) {
      fail("the outer loop has no area (its vertices are collinear), so no hole can lie in it");
    }
    warn(std::string("zero area (") +
         (too_few ? "fewer than 3 distinct vertices" : "collinear vertices") +
         "): kept, with area 0");
    face.parts.push_back(std::move(polygon));
    return face;
  }

  std::vector<std::string> loop_names{outer_name};
  {
    std::vector<hsr::Loop3> holes;
    for (std::size_t k = 0; k < polygon.holes.size(); ++k) {
      if (hsr::all_collinear(polygon.holes[k])) {
        warn("hole " + std::to_string(k) + " has no area (collinear vertices): ignored");
        continue;
      }
      holes.push_back(std::move(polygon.holes[k]));
      loop_names.push_back("hole " + std::to_string(k));
    }
    polygon.holes = std::move(holes);
  }

  const glm::dvec3 normal = hsr::plane_of(polygon).normal;
  const bool has_normal = finite(normal) && normal != glm::dvec3(0.0);
  const Planarity flat = has_normal ? planarity(polygon, normal) : Planarity{};
  const bool planar = !(flat.deviation > kPlanarityTolerance * flat.extent);
  const std::string how_far =
      planar ? std::string()
             : "a vertex lies " + short_number(flat.deviation) + " from the best-fit plane, " +
                   short_number(flat.deviation / flat.extent) +
                   " of the face's extent; tolerance " + short_number(kPlanarityTolerance);
  if (!planar && strict) fail("not planar (" + how_far + ")");

  // A planar face is checked in its exact chart; a non-planar one in its projection on
  // the best-fit plane, where it will be triangulated (a coordinate chart could fold it).
  std::vector<clipper::Loop2> loops;
  if (planar) {
    const hsr::PlaneChart chart =
        has_normal ? hsr::chart_facing(normal) : chart_without_normal(polygon.outer);
    loops.push_back(to_chart(polygon.outer, chart));
    for (const hsr::Loop3& hole : polygon.holes) loops.push_back(to_chart(hole, chart));
  } else {
    const PlaneFrame frame(polygon.outer[0], normal);
    loops.push_back(frame.project(polygon.outer));
    for (const hsr::Loop3& hole : polygon.holes) loops.push_back(frame.project(hole));
  }

  const LoopCheck check = check_loops(loops, loop_names);
  if (check.problem) fail(*check.problem);
  for (std::size_t k = 0; k < polygon.holes.size(); ++k) {
    if (check.counter_clockwise[k + 1] == check.counter_clockwise[0]) {
      std::reverse(polygon.holes[k].begin(), polygon.holes[k].end());
      std::reverse(loops[k + 1].begin(), loops[k + 1].end());
    }
  }
  if (planar) {
    face.parts.push_back(std::move(polygon));
    return face;
  }

  const std::optional<std::vector<clipper::Triangle>> triangles = clipper::triangulate(loops);
  if (!triangles) fail("not planar (" + how_far + "), and could not be split into triangles");

  std::vector<glm::dvec3> vertices(polygon.outer);
  for (const hsr::Loop3& hole : polygon.holes) {
    vertices.insert(vertices.end(), hole.begin(), hole.end());
  }
  for (const clipper::Triangle& t : *triangles) {
    hsr::Loop3 corners{vertices[t[0]], vertices[t[1]], vertices[t[2]]};
    if (hsr::all_collinear(corners)) continue;  // no area in 3D either: adds nothing
    face.parts.push_back({std::move(corners), {}});
  }
  warn("not planar (" + how_far + "): split into " + std::to_string(face.parts.size()) +
       " triangles");
  return face;
}

}  // namespace shadowgen::detail
