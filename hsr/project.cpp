#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "detail/half_plane.h"
#include "hsr/convex_window.h"
#include "hsr/hidden_surface.h"
#include "hsr/plane_chart.h"

namespace shadowgen::hsr {
namespace {

// Image of every vertex as it is: the polygon lies wholly in front of a perspective eye,
// or the view is orthographic.
clipper::PolygonSet2 project_vertices(const Polygon3& polygon, const View& view) {
  auto project_loop = [&view](const Loop3& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) out.push_back(view.project(p));
    return out;
  };
  clipper::PolygonWithHoles2 p{project_loop(polygon.outer), {}};
  for (const Loop3& h : polygon.holes) p.holes.push_back(project_loop(h));
  return clipper::normalized({p});
}

// Whether every vertex of `loop`, projected as project_vertices projects it, lies
// strictly beyond one side of the rectangle `frame`. Then so does every vertex of the
// normalized image (which keeps a subset of them), and a convex window's exact test
// finds the image apart from the frame: a face beside a point light's view is settled
// before its image is made.
bool beyond_one_side(const Loop3& loop, const View& view, const clipper::Box2& frame) {
  bool left = true, right = true, below = true, above = true;
  for (const glm::dvec3& p : loop) {
    const clipper::Point2 q = view.project(p);
    left = left && q.x < frame.xmin;
    right = right && q.x > frame.xmax;
    below = below && q.y < frame.ymin;
    above = above && q.y > frame.ymax;
    if (!(left || right || below || above)) return false;
  }
  return true;
}

// Perspective, for a polygon that crosses the near plane: cut there in 3D, in the
// polygon's own plane chart, before any division by depth. Everything here is relative to
// the eye: far from the origin (a scene at 1e8) the offsets of nearby points are exact and
// small, so the cut keeps their precision instead of rounding at the scale of the
// absolute coordinates.
clipper::PolygonSet2 project_in_front(const Polygon3& polygon, const View& view) {
  auto relative = [&view](const Loop3& loop) {
    Loop3 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) out.push_back(p - view.eye());
    return out;
  };
  Polygon3 near_eye{relative(polygon.outer), {}};
  for (const Loop3& h : polygon.holes) near_eye.holes.push_back(relative(h));
  // Original vertices are lifted back exactly; only the new ones come from the plane.
  ChartedPlane chart(plane_of(near_eye).normal, near_eye.outer.front(), ChartFrom::kWorld);
  const clipper::PolygonWithHoles2 flat = chart.flatten_known(near_eye);
  // z(d) = forward · d is affine on the chart; the part in front is where z >= near.
  ChartAffine z = chart.dot_on_plane(view.forward());
  z.c -= view.near();
  const clipper::PolygonWithHoles2 keep =
      detail::half_plane_in_box(z.a, z.b, z.c, clipper::box_of(flat));
  auto lift_and_project = [&](const clipper::Loop2& loop) {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const clipper::Point2& q : loop) {
      glm::dvec3 d = chart.lift(q);
      // A new vertex on the near plane may round a hair behind it: keep it in front.
      const double depth = glm::dot(d, view.forward());
      if (depth < view.near()) d += (view.near() - depth) * view.forward();
      out.push_back(view.project_offset(d));
    }
    return out;
  };
  return clipper::normalized(
      clipper::map_loops(clipper::intersection({flat}, {keep}), lift_and_project));
}

}  // namespace

clipper::PolygonSet2 project_polygon(const Polygon3& polygon, const View& view) {
  return project_polygon(polygon, view, plane_of(polygon));
}

clipper::PolygonSet2 project_polygon(const Polygon3& polygon, const View& view,
                                     const Plane3& plane) {
  if (!view.nearness_on(plane.normal, view.offset_from_eye(polygon.outer, plane.normal))) {
    return {};  // edge-on: no area in the image
  }
  if (!view.is_perspective()) return project_vertices(polygon, view);

  double zmin = INFINITY, zmax = -INFINITY;
  auto visit = [&](const Loop3& loop) {
    for (const glm::dvec3& p : loop) {
      const double z = glm::dot(p - view.eye(), view.forward());
      zmin = std::min(zmin, z);
      zmax = std::max(zmax, z);
    }
  };
  visit(polygon.outer);
  for (const Loop3& h : polygon.holes) visit(h);
  if (zmax <= view.near()) return {};
  const std::optional<clipper::PolygonWithHoles2> window = view.window();
  if (window && zmin >= view.near() &&
      beyond_one_side(polygon.outer, view, clipper::box_of(window->outer))) {
    return {};
  }
  clipper::PolygonSet2 image =
      zmin >= view.near() ? project_vertices(polygon, view) : project_in_front(polygon, view);
  if (window) {
    // A light's view from a point has six such windows: most faces lie wholly inside one
    // of them and wholly outside the others, which the exact tests of a convex window
    // settle without a clip. Wholly outside, nothing is in view; wholly inside, the image
    // is kept as it is (the clip gives it back too, but for vertices within a hot pixel of
    // one another, which it snaps together).
    const ConvexWindow frame(*window);
    auto every_piece = [&image](auto&& test) {
      return std::all_of(image.begin(), image.end(), test);
    };
    if (every_piece(
            [&frame](const clipper::PolygonWithHoles2& p) { return frame.apart_from(p); })) {
      return {};
    }
    if (!every_piece([&frame](const clipper::PolygonWithHoles2& p) { return frame.holds(p); })) {
      image = clipper::intersection(image, {*window});
    }
  }
  return image;
}

}  // namespace shadowgen::hsr
