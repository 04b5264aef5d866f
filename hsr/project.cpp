#include <glm/geometric.hpp>
#include <unordered_map>

#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "detail/half_plane.h"
#include "hsr/hidden_surface.h"

namespace shadowgen::hsr {
namespace {

// Coordinates of a planar polygon in its own plane: the two world axes other than the
// normal's largest component. Dropping an axis is exact, so the polygon's own vertices
// keep their exact coordinates there.
struct PlaneChart {
  int drop = 2;
  Plane3 plane;

  clipper::Point2 to_chart(const glm::dvec3& p) const {
    return {p[(drop + 1) % 3], p[(drop + 2) % 3]};
  }
  glm::dvec3 lift(const clipper::Point2& q) const {
    glm::dvec3 p(0.0);
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    p[i] = q.x;
    p[j] = q.y;
    p[drop] = (plane.offset - plane.normal[i] * q.x - plane.normal[j] * q.y) / plane.normal[drop];
    return p;
  }
};

PlaneChart chart_for(const Plane3& plane) {
  const glm::dvec3 a = glm::abs(plane.normal);
  PlaneChart c;
  c.plane = plane;
  c.drop = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  return c;
}

clipper::Loop2 to_chart(const Loop3& loop, const PlaneChart& chart) {
  clipper::Loop2 out;
  out.reserve(loop.size());
  for (const glm::dvec3& p : loop) out.push_back(chart.to_chart(p));
  return out;
}

}  // namespace

clipper::PolygonSet2 project_polygon(const Polygon3& polygon, const View& view) {
  const Plane3 plane = plane_of(polygon);
  if (!view.nearness_on(plane.normal, view.offset_from_eye(polygon.outer, plane.normal))) {
    return {};  // edge-on: no area in the image
  }

  std::vector<const Loop3*> loops{&polygon.outer};
  for (const Loop3& h : polygon.holes) loops.push_back(&h);

  auto project_loop3 = [&view](const Loop3& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) out.push_back(view.project(p));
    return out;
  };

  clipper::PolygonSet2 image;
  if (!view.is_perspective()) {
    clipper::PolygonWithHoles2 p{project_loop3(polygon.outer), {}};
    for (const Loop3& h : polygon.holes) p.holes.push_back(project_loop3(h));
    return clipper::normalized({p});
  }

  // Perspective: cut at the near plane in 3D, in the polygon's own plane, before any
  // division by depth.
  double zmin = INFINITY, zmax = -INFINITY;
  for (const Loop3* l : loops) {
    for (const glm::dvec3& p : *l) {
      const double z = glm::dot(p - view.eye(), view.forward());
      zmin = std::min(zmin, z);
      zmax = std::max(zmax, z);
    }
  }
  if (zmax <= view.near()) return {};
  if (zmin >= view.near()) {
    clipper::PolygonWithHoles2 p{project_loop3(polygon.outer), {}};
    for (const Loop3& h : polygon.holes) p.holes.push_back(project_loop3(h));
    image = clipper::normalized({p});
  } else {
    // Everything here is relative to the eye: far from the origin (a scene at 1e8) the
    // offsets of nearby points are exact and small, so the cut keeps their precision
    // instead of rounding at the scale of the absolute coordinates.
    auto relative = [&view](const Loop3& loop) {
      Loop3 out;
      out.reserve(loop.size());
      for (const glm::dvec3& p : loop) out.push_back(p - view.eye());
      return out;
    };
    Polygon3 near_eye{relative(polygon.outer), {}};
    for (const Loop3& h : polygon.holes) near_eye.holes.push_back(relative(h));
    const PlaneChart chart = chart_for(plane_of(near_eye));
    clipper::PolygonWithHoles2 flat{to_chart(near_eye.outer, chart), {}};
    for (const Loop3& h : near_eye.holes) flat.holes.push_back(to_chart(h, chart));
    // Original vertices are lifted back exactly; only the new ones come from the plane.
    std::unordered_map<clipper::Point2, glm::dvec3, clipper::Point2Hash> original;
    for (const glm::dvec3& p : near_eye.outer) original.emplace(chart.to_chart(p), p);
    for (const Loop3& h : near_eye.holes) {
      for (const glm::dvec3& p : h) original.emplace(chart.to_chart(p), p);
    }
    // z(d) = forward · d is affine on the chart: z = fx·u + fy·v + f0.
    const int i = (chart.drop + 1) % 3, j = (chart.drop + 2) % 3, k = chart.drop;
    const glm::dvec3& f = view.forward();
    const glm::dvec3& n = chart.plane.normal;
    const double fx = f[i] - f[k] * n[i] / n[k];
    const double fy = f[j] - f[k] * n[j] / n[k];
    const double f0 = f[k] * chart.plane.offset / n[k] - view.near();
    clipper::Box2 box;
    for (const clipper::Point2& q : flat.outer) box.add(q);
    const clipper::PolygonWithHoles2 keep = detail::half_plane_in_box(fx, fy, f0, box);
    const clipper::PolygonSet2 front = clipper::intersection({flat}, {keep});
    auto lift_and_project = [&](const clipper::Loop2& loop) {
      clipper::Loop2 out;
      out.reserve(loop.size());
      for (const clipper::Point2& q : loop) {
        const auto it = original.find(q);
        glm::dvec3 d = it != original.end() ? it->second : chart.lift(q);
        // A new vertex on the near plane may round a hair behind it: keep it in front.
        const double z = glm::dot(d, view.forward());
        if (z < view.near()) d += (view.near() - z) * view.forward();
        out.push_back(view.project_offset(d));
      }
      return out;
    };
    clipper::PolygonSet2 projected;
    for (const clipper::PolygonWithHoles2& piece : front) {
      clipper::PolygonWithHoles2 p{lift_and_project(piece.outer), {}};
      for (const clipper::Loop2& h : piece.holes) p.holes.push_back(lift_and_project(h));
      projected.push_back(std::move(p));
    }
    image = clipper::normalized(projected);
  }
  if (const auto window = view.window()) image = clipper::intersection(image, {*window});
  return image;
}

}  // namespace shadowgen::hsr
