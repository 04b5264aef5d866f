#include "half_plane.h"

namespace shadowgen::hsr::detail {

clipper::PolygonWithHoles2 half_plane_in_box(double a, double b, double c,
                                             const clipper::Box2& box) {
  const double gx = box.xmax - box.xmin, gy = box.ymax - box.ymin;
  const double x0 = box.xmin - gx, x1 = box.xmax + gx, y0 = box.ymin - gy, y1 = box.ymax + gy;
  const clipper::Point2 corners[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  auto value = [&](const clipper::Point2& p) { return a * p.x + b * p.y + c; };
  // Sutherland–Hodgman against one line: the rectangle is convex, so this is exact in
  // structure; the two crossing points are rounded once.
  clipper::PolygonWithHoles2 out;
  for (int i = 0; i < 4; ++i) {
    const clipper::Point2& p = corners[i];
    const clipper::Point2& q = corners[(i + 1) % 4];
    const double vp = value(p), vq = value(q);
    if (vp >= 0.0) out.outer.push_back(p);
    if ((vp >= 0.0) != (vq >= 0.0)) {
      const double t = vp / (vp - vq);
      out.outer.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  if (out.outer.size() < 3) out.outer.clear();
  return out;
}

}  // namespace shadowgen::hsr::detail
