#include "loop_geometry.h"

#include "clipper/predicates.h"

namespace shadowgen::scene::detail {

namespace {

using clipper::orient2d;
using clipper::Orientation;
using clipper::Point2;

int sign(Orientation o) { return static_cast<int>(o); }

}  // namespace

CleanLoop clean(const clipper::Loop2& loop) {
  CleanLoop c;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (!c.points.empty() && loop[i] == c.points.back()) continue;
    c.points.push_back(loop[i]);
    c.original.push_back(i);
  }
  while (c.points.size() > 1 && c.points.back() == c.points.front()) {
    c.points.pop_back();
    c.original.pop_back();
  }
  return c;
}

std::string vertex_name(const CleanLoop& loop, std::size_t clean_index) {
  return std::to_string(loop.original[clean_index % loop.points.size()]);
}

bool left_of(const Corner& c, const Point2& w) {
  const int turn = sign(orient2d(c.prev, c.at, c.next));
  const bool left_of_in = orient2d(c.prev, c.at, w) == Orientation::kCounterClockwise;
  const bool left_of_out = orient2d(c.at, c.next, w) == Orientation::kCounterClockwise;
  if (turn > 0) return left_of_in && left_of_out;
  return left_of_in || left_of_out;  // reflex, or straight (then both agree)
}

bool cross(const Corner& a, const Corner& b) {
  return left_of(a, b.prev) != left_of(a, b.next) || left_of(b, a.prev) != left_of(b, a.next);
}

bool inside_loop(const std::vector<Point2>& loop, const Point2& p) {
  bool inside = false;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[(i + 1) % n];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    // The edge crosses the horizontal line through p; count it when it does so right of p.
    const Orientation o = orient2d(a, b, p);
    if (b.y > a.y ? o == Orientation::kCounterClockwise : o == Orientation::kClockwise) {
      inside = !inside;
    }
  }
  return inside;
}

int winding(const Point2& a, const Point2& b, const Point2& x) {
  if (a.y <= x.y) {
    if (b.y > x.y && orient2d(a, b, x) == Orientation::kCounterClockwise) return 1;
  } else if (b.y <= x.y && orient2d(a, b, x) == Orientation::kClockwise) {
    return -1;
  }
  return 0;
}

bool angle_less(const Point2& p, const Point2& q1, const Point2& q2) {
  auto upper = [&p](const Point2& q) { return q.y > p.y || (q.y == p.y && q.x > p.x); };
  if (upper(q1) != upper(q2)) return upper(q1);
  return orient2d(p, q1, q2) == Orientation::kCounterClockwise;
}

}  // namespace shadowgen::scene::detail
