#include "hsr/convex_window.h"

#include <algorithm>

#include "clipper/predicates.h"

namespace shadowgen::hsr {
namespace {

int sign_of(clipper::Orientation o) { return static_cast<int>(o); }

// For exactly collinear a, b, c: does the boundary run on through b (not turn back)?
// Signs of coordinate differences are exact, and the two steps are parallel, so one
// nonzero coordinate decides.
bool runs_on(const clipper::Point2& a, const clipper::Point2& b, const clipper::Point2& c) {
  auto sign = [](double d) { return (d > 0.0) - (d < 0.0); };
  if (a.x != b.x) return sign(b.x - a.x) == sign(c.x - b.x);
  return sign(b.y - a.y) == sign(c.y - b.y);
}

// Is every point of `points` on the closed side of edge line a -> b away from a loop
// turning `turn`? Then the loop's region and the points' hull share no area.
bool all_outside(const clipper::Point2& a, const clipper::Point2& b, int turn,
                 const clipper::Loop2& points) {
  return std::all_of(points.begin(), points.end(), [&](const clipper::Point2& p) {
    return sign_of(clipper::orient2d(a, b, p)) * turn <= 0;
  });
}

// Is there an edge of the convex `loop` (turning `turn`) with all of `points` beyond it?
bool separated_by_edge_of(const clipper::Loop2& loop, int turn, const clipper::Loop2& points) {
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    if (all_outside(loop[i], loop[i + 1 == n ? 0 : i + 1], turn, points)) return true;
  }
  return false;
}

// Is every point of `points` on the closed inner side of every edge of the convex `loop`?
bool within(const clipper::Loop2& loop, int turn, const clipper::Loop2& points) {
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    const clipper::Point2& a = loop[i];
    const clipper::Point2& b = loop[i + 1 == n ? 0 : i + 1];
    for (const clipper::Point2& p : points) {
      if (sign_of(clipper::orient2d(a, b, p)) * turn < 0) return false;
    }
  }
  return true;
}

// The convex hull of `points`, counter-clockwise, without straight-run vertices (Andrew's
// monotone chain on exact orientations); fewer than three points when it has no area.
clipper::Loop2 convex_hull(clipper::Loop2 points) {
  auto less = [](const clipper::Point2& a, const clipper::Point2& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
  };
  std::sort(points.begin(), points.end(), less);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return {};
  clipper::Loop2 hull(2 * points.size());
  std::size_t k = 0;
  auto keep_left_turns = [&](const clipper::Point2& p, std::size_t floor) {
    while (k >= floor && clipper::orient2d(hull[k - 2], hull[k - 1], p) !=
                             clipper::Orientation::kCounterClockwise) {
      --k;
    }
    hull[k++] = p;
  };
  for (const clipper::Point2& p : points) keep_left_turns(p, 2);  // lower chain
  const std::size_t lower = k + 1;
  for (std::size_t i = points.size() - 1; i-- > 0;) keep_left_turns(points[i], lower);  // upper
  hull.resize(k - 1);  // the last point is the first again
  return hull;
}

}  // namespace

int convex_turn(const clipper::Loop2& loop) {
  const std::size_t n = loop.size();
  if (n < 3) return 0;
  int turn = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const clipper::Point2& a = loop[i];
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const clipper::Point2& b = loop[j];
    const clipper::Point2& c = loop[j + 1 == n ? 0 : j + 1];
    if (a == b) return 0;
    const int s = sign_of(clipper::orient2d(a, b, c));
    if (s == 0) {
      if (!runs_on(a, b, c)) return 0;
      continue;
    }
    if (turn == 0) turn = s;
    if (s != turn) return 0;
  }
  // A simple loop turning one way throughout is convex (the clipper's loops are simple).
  return turn;
}

ConvexWindow::ConvexWindow(const clipper::PolygonWithHoles2& window)
    : window_(window), turn_(convex_turn(window.outer)) {
  if (turn_ == 0) hull_ = convex_hull(window.outer);
}

bool ConvexWindow::apart_from(const clipper::PolygonWithHoles2& subject) const {
  // Beside the window: an edge line of the window's hull (its outer loop when convex)
  // with the whole subject on or beyond it.
  const bool beside = turn_ != 0
                          ? separated_by_edge_of(window_.outer, turn_, subject.outer)
                          : hull_.size() >= 3 && separated_by_edge_of(hull_, 1, subject.outer);
  if (beside) return true;
  const int subject_turn = convex_turn(subject.outer);
  return subject_turn != 0 && separated_by_edge_of(subject.outer, subject_turn, window_.outer);
}

bool ConvexWindow::holds(const clipper::PolygonWithHoles2& subject) const {
  return turn_ != 0 && window_.holes.empty() && within(window_.outer, turn_, subject.outer);
}

std::optional<clipper::ClipResult> ConvexWindow::clip_unless_apart(
    const clipper::PolygonWithHoles2& subject) const {
  // A loop without area is the clipper's to drop.
  if (subject.outer.size() < 3) return clipper::clip(subject, window_);
  if (apart_from(subject)) return std::nullopt;
  if (holds(subject)) return clipper::ClipResult{{subject}, {}};
  if (!region_) region_.emplace(window_);
  return region_->clip(subject);
}

clipper::ClipResult ConvexWindow::clip(const clipper::PolygonWithHoles2& subject) const {
  std::optional<clipper::ClipResult> r = clip_unless_apart(subject);
  if (!r) return {{}, {subject}};
  return std::move(*r);
}

}  // namespace shadowgen::hsr
