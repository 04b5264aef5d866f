#include "grazing_light.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "hsr/plane_chart.h"
#include "hsr/vector_length.h"

namespace shadowgen::detail {
namespace {

constexpr double kGrazingSine = 0x1p-20;
constexpr double kSlabReach = 0x1p30;
constexpr double kLampMargin = 0x1p-40;

struct Box3 {
  glm::dvec3 lo{INFINITY}, hi{-INFINITY};
  void add(const hsr::Loop3& loop) {
    for (const glm::dvec3& v : loop) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  }
};

clipper::PolygonWithHoles2 rectangle(double xmin, double ymin, double xmax, double ymax) {
  return {{{xmin, ymin}, {xmax, ymin}, {xmax, ymax}, {xmin, ymax}}, {}};
}

// The box of a loop grown by its size on every side, so polygons inside it stay clear of
// its border.
clipper::PolygonWithHoles2 grown_box(const clipper::Loop2& loop) {
  const auto [left, right] = std::minmax_element(
      loop.begin(), loop.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  const auto [bottom, top] = std::minmax_element(
      loop.begin(), loop.end(), [](const auto& a, const auto& b) { return a.y < b.y; });
  const double gx = right->x - left->x, gy = top->y - bottom->y;
  return rectangle(left->x - gx, bottom->y - gy, right->x + gx, top->y + gy);
}

// The face's plane: heights above it, and its chart relative to a vertex.
struct FaceFrame {
  const hsr::ChartedPlane& plane;
  const glm::dvec3& origin() const { return plane.origin(); }
  const glm::dvec3& normal() const { return plane.normal(); }
  // Chart coordinates of an offset from the origin.
  clipper::Point2 chart(const glm::dvec3& offset) const { return plane.chart()(offset); }
  double height(const glm::dvec3& p) const { return glm::dot(normal(), p - origin()); }
};

// Where the light sends a point of an occluder onto the face's plane.
struct Projection {
  const FaceFrame& face;
  const Light& light;
  double slab;
  double t_max;

  // A point p (relative to the face's origin) at height t·slab above the face.
  clipper::Point2 operator()(const glm::dvec3& p, double t) const {
    if (light.type == LightType::kDirectional) {
      // Along the light by the height over its normal component.
      const double along = glm::dot(face.normal(), light.direction);
      return face.chart(p - (t * slab / along) * light.direction);
    }
    // From the lamp through the point, to height 0: scaled by slab / (slab − h).
    const glm::dvec3 lamp = light.position - face.origin();
    return face.chart(lamp + (p - lamp) / (1.0 - t));
  }
};

// The shadow of `occluder` on the face's plane, in the face's chart.
clipper::PolygonSet2 shadow_of(const hsr::Polygon3& occluder, const glm::dvec3& occluder_normal,
                               const Projection& project) {
  const FaceFrame& face = project.face;
  const glm::dvec3 g = face.normal() - glm::dot(face.normal(), occluder_normal) * occluder_normal;
  const double g2 = glm::dot(g, g);
  const glm::dvec3 l = glm::cross(occluder_normal, face.normal());
  const double l_length = glm::length(l);
  if (g2 == 0.0 || l_length == 0.0) {
    // Parallel to the face: one height, every vertex moved as it is.
    clipper::PolygonSet2 moved{{{}, {}}};
    auto move = [&](const hsr::Loop3& loop) {
      clipper::Loop2 out;
      for (const glm::dvec3& v : loop) {
        const double t = face.height(v) / project.slab;
        if (!(t > 0.0 && t <= project.t_max)) return clipper::Loop2{};
        out.push_back(project(v - face.origin(), t));
      }
      return out;
    };
    moved[0].outer = move(occluder.outer);
    if (moved[0].outer.empty()) return {};
    for (const hsr::Loop3& h : occluder.holes) moved[0].holes.push_back(move(h));
    return clipper::normalized(moved);
  }
  const glm::dvec3 along_l = l / l_length;
  const glm::dvec3& v0 = occluder.outer.front();
  const glm::dvec3 x0 = (v0 - face.origin()) - (face.height(v0) / g2) * g;
  const glm::dvec3 m = (project.slab / g2) * g;
  auto to_st = [&](const hsr::Loop3& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& v : loop) {
      out.push_back({glm::dot(v - v0, along_l), face.height(v) / project.slab});
    }
    return out;
  };
  clipper::PolygonWithHoles2 st{to_st(occluder.outer), {}};
  for (const hsr::Loop3& h : occluder.holes) st.holes.push_back(to_st(h));
  double smin = INFINITY, smax = -INFINITY;
  for (const clipper::Point2& q : st.outer) {
    smin = std::min(smin, q.x);
    smax = std::max(smax, q.x);
  }
  const double margin = smax - smin;
  const clipper::PolygonWithHoles2 band =
      rectangle(smin - margin, 0.0, smax + margin, project.t_max);

  auto to_face = [&](const clipper::Loop2& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const clipper::Point2& q : loop) out.push_back(project(x0 + q.x * along_l + q.y * m, q.y));
    return out;
  };
  return clipper::normalized(clipper::map_loops(clipper::intersection({st}, {band}), to_face));
}

// sin θ of the text above, for a light reaching the face's front side.
double grazing_sine(const hsr::Polygon3& part, const hsr::Plane3& plane, const Light& light) {
  if (light.type == LightType::kDirectional) {
    return std::fabs(glm::dot(plane.normal, light.direction)) / hsr::stable_length(light.direction);
  }
  double farthest = 0.0;
  for (const glm::dvec3& v : part.outer)
    farthest = std::max(farthest, glm::length(v - light.position));
  const double height = glm::dot(plane.normal, light.position - part.outer.front());
  return farthest > 0.0 ? std::fabs(height) / farthest : 0.0;
}

}  // namespace

Incidence incidence(const hsr::Polygon3& part, const hsr::Plane3& plane, const Light& light) {
  const double sine = grazing_sine(part, plane, light);
  if (sine == 0.0) return Incidence::kInPlane;
  return sine < kGrazingSine ? Incidence::kGrazing : Incidence::kOpen;
}

std::vector<hsr::Polygon3> lit_by_grazing_light(std::size_t part,
                                                std::span<const hsr::Polygon3> polygons,
                                                std::span<const hsr::Plane3> planes,
                                                std::span<const int> coplanar, const Light& light) {
  const hsr::Polygon3& face = polygons[part];
  hsr::ChartedPlane plane(planes[part].normal, face.outer.front(), hsr::ChartFrom::kOrigin);
  const clipper::PolygonWithHoles2 region = plane.flatten_known(face);
  const FaceFrame frame{plane};
  const double sine = grazing_sine(face, planes[part], light);
  const clipper::PolygonSet2 around{grown_box(region.outer)};
  Box3 face_box;
  face_box.add(face.outer);
  const bool point = light.type == LightType::kPoint;

  std::vector<clipper::PolygonWithHoles2> shadows;
  for (std::size_t j = 0; j < polygons.size(); ++j) {
    if (j == part || (coplanar[part] >= 0 && coplanar[j] == coplanar[part])) continue;
    const glm::dvec3& normal = planes[j].normal;
    if (glm::length(normal) == 0.0) continue;
    double slab;
    if (point) {
      slab = frame.height(light.position);
    } else {
      if (glm::dot(normal, light.direction) == 0.0) continue;  // edge-on: no shadow area
      Box3 both = face_box;
      both.add(polygons[j].outer);
      slab = kSlabReach * glm::length(both.hi - both.lo) * sine;
    }
    if (!(slab > 0.0)) continue;
    bool ahead = false, within = false;
    for (const glm::dvec3& v : polygons[j].outer) {
      const double h = frame.height(v);
      ahead = ahead || h > 0.0;
      within = within || h < slab;
    }
    if (!ahead || !within) continue;
    const Projection project{frame, light, slab, point ? 1.0 - kLampMargin : 1.0};
    const clipper::PolygonSet2 shadow = shadow_of(polygons[j], normal, project);
    if (shadow.empty()) continue;
    for (clipper::PolygonWithHoles2& p : clipper::intersection(shadow, around)) {
      shadows.push_back(std::move(p));
    }
  }
  return plane.lift(clipper::clip(region, shadows).outside);
}

}  // namespace shadowgen::detail
