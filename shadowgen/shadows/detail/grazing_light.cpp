#include "grazing_light.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "hsr/plane_chart.h"
#include "hsr/vector_length.h"

namespace shadowgen::shadows::detail {
namespace {

constexpr double kGrazingSine = 0x1p-20;
constexpr double kSlabReach = 0x1p30;
constexpr double kEdgeOnSine = 0x1p-52;

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
//
// A point is given by its level in the slab and its offset from the level's anchor: for a
// directional light the level is t = h / slab (0 on the face's plane, 1 at the slab's
// top) and the anchor the face's origin; for a point light the level is u = (slab − h) /
// slab, the lamp's height above the point over its height above the face (1 on the
// face's plane, 0 at the lamp's height), and the anchor the lamp. u is taken from the
// lamp's own height above the point, so a point a hair below the lamp keeps a level
// precise to its own rounding, and its shadow, at 1/u of its distance, its direction.
struct Projection {
  const FaceFrame& face;
  const Light& light;
  double slab;

  bool point() const { return light.type == LightType::kPoint; }
  glm::dvec3 lamp() const { return light.position - face.origin(); }

  double level(const glm::dvec3& v) const {
    return point() ? glm::dot(face.normal(), light.position - v) / slab : face.height(v) / slab;
  }
  // The offset of v from the anchor.
  glm::dvec3 offset(const glm::dvec3& v) const {
    return point() ? v - light.position : v - face.origin();
  }

  // The point at `offset` from the anchor, at `level`, sent onto the face's plane.
  clipper::Point2 operator()(const glm::dvec3& offset, double level) const {
    if (!point()) {
      // Along the light by the height over its normal component.
      const double along = glm::dot(face.normal(), light.direction);
      return face.chart(offset - (level * slab / along) * light.direction);
    }
    // From the lamp through the point, to height 0: its offset scaled by slab / (slab − h).
    return face.chart(lamp() + offset / level);
  }
};

// The greatest chart distance from `from` to a corner of `box` (a rectangle).
double farthest_corner(const clipper::PolygonWithHoles2& box, const clipper::Point2& from) {
  double farthest = 0.0;
  for (const clipper::Point2& c : box.outer) {
    farthest = std::max(farthest, std::hypot(c.x - from.x, c.y - from.y));
  }
  return farthest;
}

// The part of `loop`, charted as (s, level), at levels from `lo` to `hi`: Sutherland–
// Hodgman on the two lines, exact in winding number; the points it adds lie on the lines,
// at their levels exactly. (The clipper would snap a level far below its s to 0.)
clipper::Loop2 within_levels(const clipper::Loop2& loop, double lo, double hi) {
  auto cut = [](const clipper::Loop2& in, double level, bool keep_above) {
    clipper::Loop2 out;
    for (std::size_t i = 0; i < in.size(); ++i) {
      const clipper::Point2& p = in[i];
      const clipper::Point2& q = in[(i + 1) % in.size()];
      const bool p_in = keep_above ? p.y >= level : p.y <= level;
      const bool q_in = keep_above ? q.y >= level : q.y <= level;
      if (p_in) out.push_back(p);
      if (p_in != q_in) out.push_back({p.x + (q.x - p.x) * ((level - p.y) / (q.y - p.y)), level});
    }
    return out;
  };
  return cut(cut(loop, lo, true), hi, false);
}

// The least level u a point light's shadow of a sloping occluder needs, charted from the
// occluder's line at the lamp's height, anchor + s·along (chart `top`, `along`), with
// `rise` the chart offset from level 0 to level 1 and `s_reach` the largest |s| charted.
// The occluder's points at level u lie on a line whose shadow lies at least d/u − |rise|
// from the lamp's foot, d the foot's distance to the chart of the line at the lamp's
// height: cut at u = d / (2 (reach + |rise|)), the shadow leaves `reach`, the face's box,
// before the cut. Where d is within 2^-52 of its own terms' size the lamp lies in the
// occluder's plane to within their rounding, the occluder is edge-on to it and casts a
// wedge as thin; d is taken no smaller, so no shadow point grows past 2^53 times the box.
double least_lamp_level(const clipper::Point2& top, const clipper::Point2& along,
                        const clipper::Point2& rise, double s_reach, double reach) {
  const double along_length = std::hypot(along.x, along.y);
  const double d = std::fabs(top.x * along.y - top.y * along.x) / along_length;
  const double terms = std::hypot(top.x, top.y) + s_reach * along_length;
  return std::max(d, kEdgeOnSine * terms) / (2.0 * (reach + std::hypot(rise.x, rise.y)));
}

// The shadow of `occluder` on the face's plane, in the face's chart. `reach`: the
// greatest chart distance from the lamp's foot to the face's box, for a point light.
clipper::PolygonSet2 shadow_of(const hsr::Polygon3& occluder, const glm::dvec3& occluder_normal,
                               const Projection& project, double reach) {
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
        const double level = project.level(v);
        const bool casts =
            project.point() ? level > 0.0 && level < 1.0 : level > 0.0 && level <= 1.0;
        if (!casts) return clipper::Loop2{};
        out.push_back(project(project.offset(v), level));
      }
      return out;
    };
    moved[0].outer = move(occluder.outer);
    if (moved[0].outer.empty()) return {};
    for (const hsr::Loop3& h : occluder.holes) moved[0].holes.push_back(move(h));
    return clipper::normalized(moved);
  }
  // The occluder's plane charted as anchor + s·along_l + level·rise: for a directional
  // light from its line on the face's plane up, for a point light from its line at the
  // lamp's height down.
  const glm::dvec3 along_l = l / l_length;
  const glm::dvec3& v0 = occluder.outer.front();
  const glm::dvec3 m = (project.slab / g2) * g;  // one slab up, in the occluder's plane
  const glm::dvec3 anchor =
      project.point()
          ? project.offset(v0) + (glm::dot(face.normal(), project.light.position - v0) / g2) * g
          : project.offset(v0) - (face.height(v0) / g2) * g;
  const glm::dvec3 rise = project.point() ? -m : m;
  auto to_chart = [&](const hsr::Loop3& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& v : loop) out.push_back({glm::dot(v - v0, along_l), project.level(v)});
    return out;
  };
  double lowest = 0.0;
  if (project.point()) {
    double s_reach = 0.0;
    for (const glm::dvec3& v : occluder.outer) {
      s_reach = std::max(s_reach, std::fabs(glm::dot(v - v0, along_l)));
    }
    lowest =
        least_lamp_level(face.chart(anchor), face.chart(along_l), face.chart(rise), s_reach, reach);
    if (!(lowest > 0.0 && lowest < 1.0)) return {};  // edge-on, or wholly beyond the box
  }
  auto to_face = [&](const clipper::Loop2& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const clipper::Point2& q : loop) {
      out.push_back(project(anchor + q.x * along_l + q.y * rise, q.y));
    }
    return out;
  };
  clipper::PolygonSet2 cast{{to_face(within_levels(to_chart(occluder.outer), lowest, 1.0)), {}}};
  if (cast[0].outer.size() < 3) return {};
  for (const hsr::Loop3& h : occluder.holes) {
    clipper::Loop2 hole = within_levels(to_chart(h), lowest, 1.0);
    if (hole.size() >= 3) cast[0].holes.push_back(to_face(hole));
  }
  return clipper::normalized(cast);
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
  const double reach =
      point ? farthest_corner(around[0], frame.chart(light.position - frame.origin())) : 0.0;

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
    const Projection project{frame, light, slab};
    const clipper::PolygonSet2 shadow = shadow_of(polygons[j], normal, project, reach);
    if (shadow.empty()) continue;
    for (clipper::PolygonWithHoles2& p : clipper::intersection(shadow, around)) {
      shadows.push_back(std::move(p));
    }
  }
  return plane.lift(clipper::clip(region, shadows).outside);
}

}  // namespace shadowgen::shadows::detail
