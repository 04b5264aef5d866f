#include "shadowgen/detail/grazing_light.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "shadowgen/detail/plane_lifter.h"

namespace shadowgen::detail {
namespace {

constexpr double kGrazingSine = 0x1p-20;
constexpr double kSlabReach = 0x1p30;

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
  glm::dvec3 origin;
  glm::dvec3 normal;
  PlaneChart chart;
  double height(const glm::dvec3& p) const { return glm::dot(normal, p - origin); }
};

// The shadow of `occluder` on the face's plane along `direction`, in the face's chart:
// the occluder's part at heights 0 <= h <= slab in front of the face, moved along the
// light onto the plane.
//
// The slab can be far thinner than a rounding of the occluder's coordinates (a sun 1e-40
// from grazing), so the occluder is charted in coordinates where it is not: s along the
// line L where the occluder's plane meets the face's, t = h / slab. The cut to 0 <= t <= 1
// is then as well-conditioned as any clip, and the projection is affine in (s, t) with
// moderate coefficients: a point x0 + s·l + t·m of the occluder's plane (x0 on L, l along
// L, m across it with height slab) lands at x0 + s·l + t·(m − slab/(n·d)·d), every term
// within 2^30 of the size of the face and occluder.
clipper::PolygonSet2 shadow_of(const hsr::Polygon3& occluder, const glm::dvec3& occluder_normal,
                               const FaceFrame& face, const glm::dvec3& direction, double slab) {
  const double along = glm::dot(face.normal, direction);
  const glm::dvec3 g = face.normal - glm::dot(face.normal, occluder_normal) * occluder_normal;
  const double g2 = glm::dot(g, g);
  const glm::dvec3 l = glm::cross(occluder_normal, face.normal);
  const double l_length = glm::length(l);
  if (g2 == 0.0 || l_length == 0.0) {
    // Parallel to the face: one height, a plain translation along the light.
    clipper::PolygonSet2 moved{{{}, {}}};
    auto move = [&](const hsr::Loop3& loop) {
      clipper::Loop2 out;
      for (const glm::dvec3& v : loop) {
        const double h = face.height(v);
        if (!(h > 0.0 && h <= slab)) return clipper::Loop2{};
        out.push_back(face.chart((v - face.origin) - (h / along) * direction));
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
  const glm::dvec3 x0_from_face = (v0 - face.origin) - (face.height(v0) / g2) * g;
  auto to_st = [&](const hsr::Loop3& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& v : loop) {
      out.push_back({glm::dot(v - v0, along_l), face.height(v) / slab});
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
  const clipper::PolygonWithHoles2 band = rectangle(smin - margin, 0.0, smax + margin, 1.0);

  const clipper::Point2 x0 = face.chart(x0_from_face);
  const clipper::Point2 ls = face.chart(along_l);
  const clipper::Point2 mt = face.chart((slab / g2) * g - (slab / along) * direction);
  auto to_face = [&](const clipper::Loop2& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const clipper::Point2& q : loop) {
      out.push_back({x0.x + q.x * ls.x + q.y * mt.x, x0.y + q.x * ls.y + q.y * mt.y});
    }
    return out;
  };
  clipper::PolygonSet2 shadow;
  for (const clipper::PolygonWithHoles2& piece : clipper::intersection({st}, {band})) {
    clipper::PolygonWithHoles2 p{to_face(piece.outer), {}};
    for (const clipper::Loop2& h : piece.holes) p.holes.push_back(to_face(h));
    shadow.push_back(std::move(p));
  }
  return clipper::normalized(shadow);
}

}  // namespace

bool grazes(const hsr::Plane3& plane, const glm::dvec3& direction) {
  const double sine = std::fabs(glm::dot(plane.normal, direction)) / glm::length(direction);
  return sine > 0.0 && sine < kGrazingSine;
}

std::vector<hsr::Polygon3> lit_by_grazing_light(std::size_t part,
                                                std::span<const hsr::Polygon3> polygons,
                                                std::span<const hsr::Plane3> planes,
                                                std::span<const int> coplanar,
                                                const glm::dvec3& direction) {
  const hsr::Polygon3& face = polygons[part];
  const FaceFrame frame{face.outer.front(), planes[part].normal, chart_facing(planes[part].normal)};
  const double sine = std::fabs(glm::dot(frame.normal, direction)) / glm::length(direction);
  PlaneLifter lifter(planes[part], frame.origin);
  const clipper::PolygonWithHoles2 region = lifter.flatten(face);
  const clipper::PolygonSet2 around{grown_box(region.outer)};
  Box3 face_box;
  face_box.add(face.outer);

  std::vector<clipper::PolygonWithHoles2> shadows;
  for (std::size_t j = 0; j < polygons.size(); ++j) {
    if (j == part || (coplanar[part] >= 0 && coplanar[j] == coplanar[part])) continue;
    const glm::dvec3& normal = planes[j].normal;
    if (glm::length(normal) == 0.0 || glm::dot(normal, direction) == 0.0) continue;
    // Beyond this height a point's shadow lands more than twice the size of face and
    // occluder together away from it: it cannot fall on the face.
    Box3 both = face_box;
    both.add(polygons[j].outer);
    const double slab = kSlabReach * glm::length(both.hi - both.lo) * sine;
    if (!(slab > 0.0)) continue;
    bool ahead = false, within = false;
    for (const glm::dvec3& v : polygons[j].outer) {
      const double h = frame.height(v);
      ahead = ahead || h > 0.0;
      within = within || h < slab;
    }
    if (!ahead || !within) continue;
    const clipper::PolygonSet2 shadow = shadow_of(polygons[j], normal, frame, direction, slab);
    if (shadow.empty()) continue;
    for (clipper::PolygonWithHoles2& p : clipper::intersection(shadow, around)) {
      shadows.push_back(std::move(p));
    }
  }
  return lifter.lift(clipper::clip(region, shadows).outside);
}

}  // namespace shadowgen::detail
