// The only translation unit of the project that includes CGAL.
//
// Two kernels: areas and set operations use Epeck (exact constructions: intersection
// points are exact rationals); validity checks only ask yes/no questions about the
// double coordinates themselves, so Epick's exact filtered predicates suffice and keep
// them fast (no constructions there, except one rare fallback in Epeck).

#include "tests/support/cgal_oracle.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Gps_segment_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include <vector>

namespace shadowgen::test {
namespace {

using clipper::Loop2;
using clipper::Point2;

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = Kernel::Point_2;
using ExactPolygon = CGAL::Polygon_2<Kernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using ExactPolygonSet = CGAL::Polygon_set_2<Kernel>;
using ExactNumber = Kernel::FT;

using FilteredKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using FPoint = FilteredKernel::Point_2;
using FSegment = FilteredKernel::Segment_2;

std::string format_point(const Point2& p) {
  std::ostringstream out;
  out.precision(17);
  out << '(' << p.x << ' ' << p.y << ')';
  return out.str();
}

// --- conversion to the exact kernel -------------------------------------------------

// Repeated consecutive vertices (and an explicit closing vertex) dropped; orientation
// set to `wanted`. Empty when no area is left.
std::optional<ExactPolygon> to_exact_loop(const Loop2& loop, CGAL::Orientation wanted) {
  std::vector<ExactPoint> points;
  points.reserve(loop.size());
  const Point2* previous = nullptr;
  for (const Point2& p : loop) {
    if (previous == nullptr || !(p == *previous)) points.emplace_back(p.x, p.y);
    previous = &p;
  }
  while (points.size() > 1 && loop.front() == loop.back() && points.front() == points.back()) {
    points.pop_back();
  }
  if (points.size() < 3) return std::nullopt;
  ExactPolygon polygon(points.begin(), points.end());
  const CGAL::Sign sign = CGAL::sign(polygon.area());
  if (sign == CGAL::ZERO) return std::nullopt;
  if (static_cast<int>(sign) != static_cast<int>(wanted)) polygon.reverse_orientation();
  return polygon;
}

// Consecutive repeated vertices (and an explicit closing vertex) removed.
PolygonSet2 without_repeats(PolygonSet2 polygons) {
  auto tidy = [](Loop2& loop) {
    loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
    while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
  };
  for (PolygonWithHoles2& polygon : polygons) {
    tidy(polygon.outer);
    for (Loop2& hole : polygon.holes) tidy(hole);
  }
  return polygons;
}

ExactPolygonSet to_exact_set(const PolygonSet2& polygons) {
  std::vector<ExactPolygonWithHoles> parts;
  ExactPolygonSet set;
  for (const PolygonWithHoles2& polygon : polygons) {
    std::optional<ExactPolygon> outer = to_exact_loop(polygon.outer, CGAL::COUNTERCLOCKWISE);
    if (!outer) continue;
    // A hole touching the outer loop inside one of its edges is fine for clip() but not
    // for CGAL's Polygon_with_holes_2: such a polygon is built as outer loop − holes,
    // from simple polygons only.
    const bool cgal_valid =
        polygon.holes.empty() || validity_problem(oriented(without_repeats({polygon}))[0]).empty();
    std::vector<ExactPolygon> holes;
    for (const Loop2& hole : polygon.holes) {
      if (std::optional<ExactPolygon> h =
              to_exact_loop(hole, cgal_valid ? CGAL::CLOCKWISE : CGAL::COUNTERCLOCKWISE)) {
        holes.push_back(std::move(*h));
      }
    }
    if (cgal_valid) {
      parts.emplace_back(std::move(*outer), holes.begin(), holes.end());
      continue;
    }
    ExactPolygonSet piece;
    piece.insert(*outer);
    ExactPolygonSet removed;
    removed.join(holes.begin(), holes.end());
    piece.difference(removed);
    set.join(piece);
  }
  if (!parts.empty()) set.join(parts.begin(), parts.end());
  return set;
}

ExactNumber exact_area_of(const ExactPolygonSet& set) {
  std::vector<ExactPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  ExactNumber total = 0;
  for (const ExactPolygonWithHoles& part : parts) {
    total += part.outer_boundary().area();
    for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole) {
      total += hole->area();  // holes run clockwise: negative
    }
  }
  return total;
}

double to_double(const ExactNumber& value) { return CGAL::to_double(CGAL::exact(value)); }

// --- validity, with exact predicates on the doubles ------------------------------------

struct NamedLoop {
  std::string name;
  const Loop2* loop;
  int group;  // loops of one polygon share a group
};

struct Edge {
  int loop;
  std::size_t index;  // edge from vertex index to index + 1
  FPoint a, b;
  double xmin, xmax, ymin, ymax;
};

FPoint to_filtered(const Point2& p) { return FPoint(p.x, p.y); }

std::size_t next_index(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }
std::size_t previous_index(std::size_t i, std::size_t n) { return i == 0 ? n - 1 : i - 1; }

// Direction d = p - v strictly inside the open angular sector that runs counter-
// clockwise from direction (from - v) to direction (to - v). The sector's two rays are
// distinct (no spike).
bool in_open_sector(const FPoint& v, const FPoint& from, const FPoint& to, const FPoint& p) {
  const CGAL::Orientation turn = CGAL::orientation(v, from, to);
  const CGAL::Orientation from_side = CGAL::orientation(v, from, p);
  const CGAL::Orientation to_side = CGAL::orientation(v, p, to);
  if (turn == CGAL::LEFT_TURN) return from_side == CGAL::LEFT_TURN && to_side == CGAL::LEFT_TURN;
  if (turn == CGAL::RIGHT_TURN) {
    // Reflex sector: everything except the closed convex sector from `to` to `from`.
    return !(CGAL::orientation(v, to, p) != CGAL::RIGHT_TURN &&
             CGAL::orientation(v, p, from) != CGAL::RIGHT_TURN);
  }
  // Straight angle (from and to opposite): the open half-plane left of from -> to.
  return from_side == CGAL::LEFT_TURN;
}

// Which side of loop `a` the point p near vertex/edge lies on. The enclosed region of
// a counter-clockwise loop lies to the left of its edges; of a clockwise one, to the right.
bool in_enclosed_sector(const Loop2& a, bool a_ccw, std::size_t vertex, const FPoint& p) {
  const std::size_t n = a.size();
  const FPoint v = to_filtered(a[vertex]);
  const FPoint next = to_filtered(a[next_index(vertex, n)]);
  const FPoint previous = to_filtered(a[previous_index(vertex, n)]);
  return a_ccw ? in_open_sector(v, next, previous, p) : in_open_sector(v, previous, next, p);
}

bool is_ccw(const Loop2& loop) {
  std::vector<FPoint> points;
  points.reserve(loop.size());
  for (const Point2& p : loop) points.push_back(to_filtered(p));
  return CGAL::orientation_2(points.begin(), points.end(), FilteredKernel()) ==
         CGAL::COUNTERCLOCKWISE;
}

enum class Side { kInside, kOutside, kUndecided };

// Where loop b lies with respect to the region enclosed by loop a, given that their
// boundaries neither cross nor overlap (so b is wholly on one side, touching at most at
// points). Decided at the first vertex of b off a's boundary; if every vertex of b is on
// a's boundary, at the exact midpoint of an edge of b.
Side side_of(const Loop2& b, const Loop2& a) {
  std::vector<FPoint> polygon;
  polygon.reserve(a.size());
  for (const Point2& p : a) polygon.push_back(to_filtered(p));
  for (const Point2& p : b) {
    switch (
        CGAL::bounded_side_2(polygon.begin(), polygon.end(), to_filtered(p), FilteredKernel())) {
      case CGAL::ON_BOUNDED_SIDE:
        return Side::kInside;
      case CGAL::ON_UNBOUNDED_SIDE:
        return Side::kOutside;
      case CGAL::ON_BOUNDARY:
        break;
    }
  }
  std::vector<ExactPoint> exact_polygon;
  exact_polygon.reserve(a.size());
  for (const Point2& p : a) exact_polygon.emplace_back(p.x, p.y);
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Point2& p = b[i];
    const Point2& q = b[next_index(i, b.size())];
    const ExactPoint middle = CGAL::midpoint(ExactPoint(p.x, p.y), ExactPoint(q.x, q.y));
    switch (CGAL::bounded_side_2(exact_polygon.begin(), exact_polygon.end(), middle, Kernel())) {
      case CGAL::ON_BOUNDED_SIDE:
        return Side::kInside;
      case CGAL::ON_UNBOUNDED_SIDE:
        return Side::kOutside;
      case CGAL::ON_BOUNDARY:
        break;
    }
  }
  return Side::kUndecided;
}

std::string loop_shape_problem(const NamedLoop& named) {
  const Loop2& loop = *named.loop;
  for (const Point2& p : loop) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      return named.name + " has a non-finite coordinate";
    }
  }
  if (loop.size() < 3) {
    return named.name + " has " + std::to_string(loop.size()) + " vertices (at least 3 needed)";
  }
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (loop[i] == loop[next_index(i, loop.size())]) {
      return named.name + " has a zero-length edge at " + format_point(loop[i]);
    }
  }
  std::vector<Point2> sorted = loop;
  std::sort(sorted.begin(), sorted.end());
  const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
  if (repeated != sorted.end()) {
    return named.name + " visits vertex " + format_point(*repeated) + " twice";
  }
  return {};
}

// Every pair of edges whose bounding boxes meet, found by a sweep over x. For pairs of
// loops of different groups only crossings and overlaps are errors (polygons of a set
// may touch); within a group a vertex inside another loop's edge is an error too.
struct ContactCheck {
  const std::vector<NamedLoop>& loops;
  bool within_groups;            // check pairs of one group (true) or of different groups (false)
  bool any_point_within_groups;  // a vertex may touch inside an edge of its own group
  std::string problem;
  // Common vertices of two loops: (loop a, vertex in a, loop b, vertex in b), a < b.
  std::set<std::tuple<int, std::size_t, int, std::size_t>> shared_vertices;
  // Vertices of one loop on the inside of another's edge: (loop, vertex, loop, edge).
  std::set<std::tuple<int, std::size_t, int, std::size_t>> vertices_on_edges;

  void fail(std::string message) {
    if (problem.empty()) problem = std::move(message);
  }

  void run() {
    std::vector<Edge> edges;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      const Loop2& loop = *loops[l].loop;
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2& p = loop[i];
        const Point2& q = loop[next_index(i, loop.size())];
        edges.push_back({static_cast<int>(l), i, to_filtered(p), to_filtered(q), std::min(p.x, q.x),
                         std::max(p.x, q.x), std::min(p.y, q.y), std::max(p.y, q.y)});
      }
    }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& e, const Edge& f) { return e.xmin < f.xmin; });
    for (std::size_t i = 0; i < edges.size() && problem.empty(); ++i) {
      for (std::size_t j = i + 1; j < edges.size() && edges[j].xmin <= edges[i].xmax; ++j) {
        if (edges[j].ymin > edges[i].ymax || edges[j].ymax < edges[i].ymin) continue;
        const bool same_group = loops[edges[i].loop].group == loops[edges[j].loop].group;
        if (same_group != within_groups) continue;
        check_pair(edges[i], edges[j]);
        if (!problem.empty()) return;
      }
    }
    if (problem.empty()) check_shared_vertices();
    if (problem.empty()) check_vertices_on_edges();
  }

  void check_pair(const Edge& e, const Edge& f) {
    if (e.loop == f.loop) {
      check_same_loop(e, f);
      return;
    }
    if (!CGAL::do_intersect(FSegment(e.a, e.b), FSegment(f.a, f.b))) return;
    const std::string& e_name = loops[e.loop].name;
    const std::string& f_name = loops[f.loop].name;
    const CGAL::Orientation fa = CGAL::orientation(e.a, e.b, f.a);
    const CGAL::Orientation fb = CGAL::orientation(e.a, e.b, f.b);
    if (fa == CGAL::COLLINEAR && fb == CGAL::COLLINEAR) {
      // Collinear and intersecting: an overlap unless they only meet end to end.
      const bool end_to_end = (e.a == f.a && CGAL::angle(e.b, e.a, f.b) == CGAL::OBTUSE) ||
                              (e.a == f.b && CGAL::angle(e.b, e.a, f.a) == CGAL::OBTUSE) ||
                              (e.b == f.a && CGAL::angle(e.a, e.b, f.b) == CGAL::OBTUSE) ||
                              (e.b == f.b && CGAL::angle(e.a, e.b, f.a) == CGAL::OBTUSE);
      if (!end_to_end) {
        fail(e_name + " and " + f_name + " overlap along the edge from " +
             format_point(point_of(e, false)) + " to " + format_point(point_of(e, true)));
        return;
      }
    }
    const CGAL::Orientation ea = CGAL::orientation(f.a, f.b, e.a);
    const CGAL::Orientation eb = CGAL::orientation(f.a, f.b, e.b);
    if (fa != CGAL::COLLINEAR && fb != CGAL::COLLINEAR && ea != CGAL::COLLINEAR &&
        eb != CGAL::COLLINEAR) {
      fail(e_name + " and " + f_name + " cross between " + format_point(point_of(e, false)) +
           " and " + format_point(point_of(e, true)));
      return;
    }
    // They touch at an endpoint of one of them.
    const Loop2& e_loop = *loops[e.loop].loop;
    const Loop2& f_loop = *loops[f.loop].loop;
    const std::size_t e_next = next_index(e.index, e_loop.size());
    const std::size_t f_next = next_index(f.index, f_loop.size());
    const std::size_t e_ends[2] = {e.index, e_next};
    const std::size_t f_ends[2] = {f.index, f_next};
    for (std::size_t ei : e_ends) {
      for (std::size_t fi : f_ends) {
        if (e_loop[ei] == f_loop[fi]) {
          if (e.loop < f.loop) {
            shared_vertices.emplace(e.loop, ei, f.loop, fi);
          } else {
            shared_vertices.emplace(f.loop, fi, e.loop, ei);
          }
        }
      }
    }
    const FSegment e_segment(e.a, e.b);
    const FSegment f_segment(f.a, f.b);
    for (std::size_t fi : f_ends) {
      const FPoint p = to_filtered(f_loop[fi]);
      if (p != e.a && p != e.b && e_segment.has_on(p)) {
        vertices_on_edges.emplace(f.loop, fi, e.loop, e.index);
      }
    }
    for (std::size_t ei : e_ends) {
      const FPoint p = to_filtered(e_loop[ei]);
      if (p != f.a && p != f.b && f_segment.has_on(p)) {
        vertices_on_edges.emplace(e.loop, ei, f.loop, f.index);
      }
    }
  }

  Point2 point_of(const Edge& e, bool end) const {
    const Loop2& loop = *loops[e.loop].loop;
    return loop[end ? next_index(e.index, loop.size()) : e.index];
  }

  void check_same_loop(const Edge& e, const Edge& f) {
    const Loop2& loop = *loops[e.loop].loop;
    const std::size_t n = loop.size();
    const std::string& name = loops[e.loop].name;
    const bool f_follows_e = next_index(e.index, n) == f.index;
    const bool e_follows_f = next_index(f.index, n) == e.index;
    if (f_follows_e || e_follows_f) {
      // Adjacent edges meet at their common vertex; they may not fold back onto each
      // other (a spike). In a triangle, each pair is adjacent both ways: check both.
      auto folds_back = [&](const Edge& first, const Edge& second) {
        return CGAL::orientation(first.a, first.b, second.b) == CGAL::COLLINEAR &&
               CGAL::angle(first.a, first.b, second.b) == CGAL::ACUTE;
      };
      if ((f_follows_e && folds_back(e, f)) || (e_follows_f && folds_back(f, e))) {
        fail(name + " doubles back on itself at " +
             format_point(f_follows_e ? point_of(e, true) : point_of(f, true)));
      }
      return;
    }
    if (CGAL::do_intersect(FSegment(e.a, e.b), FSegment(f.a, f.b))) {
      const bool proper = CGAL::orientation(e.a, e.b, f.a) * CGAL::orientation(e.a, e.b, f.b) < 0 &&
                          CGAL::orientation(f.a, f.b, e.a) * CGAL::orientation(f.a, f.b, e.b) < 0;
      fail(name + (proper ? " crosses itself" : " touches itself (a vertex on another edge)") +
           ": edges from " + format_point(point_of(e, false)) + " to " +
           format_point(point_of(e, true)) + " and from " + format_point(point_of(f, false)) +
           " to " + format_point(point_of(f, true)));
    }
  }

  // Two loops through one vertex must not cross there: the other loop's two edges at
  // the vertex lie on the same side of this loop (neither edge lies along this loop's
  // edges, or an overlap would have been reported).
  void check_shared_vertices() {
    std::vector<int> ccw(loops.size(), -1);  // orientation per loop, found when needed
    for (const auto& [la, ia, lb, ib] : shared_vertices) {
      const Loop2& a = *loops[la].loop;
      const Loop2& b = *loops[lb].loop;
      if (ccw[la] < 0) ccw[la] = is_ccw(a) ? 1 : 0;
      const bool a_ccw = ccw[la] == 1;
      const FPoint b_next = to_filtered(b[next_index(ib, b.size())]);
      const FPoint b_previous = to_filtered(b[previous_index(ib, b.size())]);
      if (in_enclosed_sector(a, a_ccw, ia, b_next) !=
          in_enclosed_sector(a, a_ccw, ia, b_previous)) {
        fail(loops[la].name + " and " + loops[lb].name + " cross at their common vertex " +
             format_point(a[ia]));
        return;
      }
    }
  }

  void check_vertices_on_edges() {
    for (const auto& [lv, iv, le, ie] : vertices_on_edges) {
      const Loop2& v_loop = *loops[lv].loop;
      const Loop2& e_loop = *loops[le].loop;
      if (loops[lv].group == loops[le].group && !any_point_within_groups) {
        fail("vertex " + format_point(v_loop[iv]) + " of " + loops[lv].name +
             " lies inside an edge of " + loops[le].name +
             " (loops may meet only at common vertices)");
        return;
      }
      const FPoint a = to_filtered(e_loop[ie]);
      const FPoint b = to_filtered(e_loop[next_index(ie, e_loop.size())]);
      const CGAL::Orientation next_side =
          CGAL::orientation(a, b, to_filtered(v_loop[next_index(iv, v_loop.size())]));
      const CGAL::Orientation previous_side =
          CGAL::orientation(a, b, to_filtered(v_loop[previous_index(iv, v_loop.size())]));
      if (next_side != CGAL::COLLINEAR && previous_side != CGAL::COLLINEAR &&
          next_side != previous_side) {
        fail(loops[lv].name + " crosses " + loops[le].name + " at " + format_point(v_loop[iv]));
        return;
      }
    }
  }
};

std::vector<NamedLoop> named_loops(const PolygonWithHoles2& polygon, const std::string& prefix,
                                   int group) {
  std::vector<NamedLoop> loops;
  loops.push_back({prefix + "outer loop", &polygon.outer, group});
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    loops.push_back({prefix + "hole " + std::to_string(h), &polygon.holes[h], group});
  }
  return loops;
}

std::string polygon_problem(const PolygonWithHoles2& polygon, const std::string& prefix,
                            Contacts contact_rule) {
  const std::vector<NamedLoop> loops = named_loops(polygon, prefix, 0);
  for (const NamedLoop& loop : loops) {
    if (std::string problem = loop_shape_problem(loop); !problem.empty()) return problem;
  }
  ContactCheck contacts{loops, true, contact_rule == Contacts::kAnyPoint, {}, {}, {}};
  contacts.run();
  if (!contacts.problem.empty()) return contacts.problem;
  if (!is_ccw(polygon.outer)) return prefix + "outer loop runs clockwise";
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    if (is_ccw(polygon.holes[h])) return loops[h + 1].name + " runs counter-clockwise";
  }
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    if (side_of(polygon.holes[h], polygon.outer) != Side::kInside) {
      return loops[h + 1].name + " is not inside the outer loop";
    }
  }
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    for (std::size_t k = 0; k < polygon.holes.size(); ++k) {
      if (h != k && side_of(polygon.holes[h], polygon.holes[k]) != Side::kOutside) {
        return loops[h + 1].name + " lies inside " + loops[k + 1].name;
      }
    }
  }
  return {};
}

struct Box {
  double xmin = std::numeric_limits<double>::infinity();
  double xmax = -std::numeric_limits<double>::infinity();
  double ymin = std::numeric_limits<double>::infinity();
  double ymax = -std::numeric_limits<double>::infinity();
};

Box box_of(const Loop2& loop) {
  Box box;
  for (const Point2& p : loop) {
    box.xmin = std::min(box.xmin, p.x);
    box.xmax = std::max(box.xmax, p.x);
    box.ymin = std::min(box.ymin, p.y);
    box.ymax = std::max(box.ymax, p.y);
  }
  return box;
}

bool boxes_meet(const Box& a, const Box& b) {
  return a.xmin <= b.xmax && b.xmin <= a.xmax && a.ymin <= b.ymax && b.ymin <= a.ymax;
}

// Polygon `inner`'s outer loop lies in the area of polygon `outer`: that is an overlap
// unless it lies within one of outer's holes.
bool lies_in_area_of(const PolygonWithHoles2& inner, const PolygonWithHoles2& outer) {
  if (side_of(inner.outer, outer.outer) != Side::kInside) return false;
  for (const Loop2& hole : outer.holes) {
    if (side_of(inner.outer, hole) == Side::kInside) return false;
  }
  return true;
}

}  // namespace

// --- public interface --------------------------------------------------------------------

struct ExactOverlay::Impl {
  ExactPolygonSet subject;
  ExactPolygonSet clip;
  ExactPolygonSet inside;
  ExactPolygonSet outside;
};

ExactOverlay::ExactOverlay(const PolygonSet2& subject, const PolygonSet2& clip)
    : impl_(std::make_unique<Impl>()) {
  impl_->subject = to_exact_set(subject);
  impl_->clip = to_exact_set(clip);
  impl_->inside = impl_->subject;
  impl_->inside.intersection(impl_->clip);
  impl_->outside = impl_->subject;
  impl_->outside.difference(impl_->clip);
}

ExactOverlay::~ExactOverlay() = default;

ExactAreas ExactOverlay::areas() const {
  const ExactNumber subject = exact_area_of(impl_->subject);
  const ExactNumber clip = exact_area_of(impl_->clip);
  const ExactNumber inside = exact_area_of(impl_->inside);
  const ExactNumber outside = exact_area_of(impl_->outside);
  ExactAreas areas;
  areas.subject = to_double(subject);
  areas.clip = to_double(clip);
  areas.inside = to_double(inside);
  areas.outside = to_double(outside);
  areas.clip_outside = to_double(clip - inside);
  return areas;
}

double ExactOverlay::inside_discrepancy(const PolygonSet2& ours) const {
  ExactPolygonSet difference = to_exact_set(ours);
  difference.symmetric_difference(impl_->inside);
  return to_double(exact_area_of(difference));
}

double ExactOverlay::outside_discrepancy(const PolygonSet2& ours) const {
  ExactPolygonSet difference = to_exact_set(ours);
  difference.symmetric_difference(impl_->outside);
  return to_double(exact_area_of(difference));
}

ExactAreas exact_clip_areas(const PolygonSet2& subject, const PolygonSet2& clip) {
  return ExactOverlay(subject, clip).areas();
}

double exact_area(const PolygonSet2& region) {
  return to_double(exact_area_of(to_exact_set(region)));
}

double exact_area_of_pieces(const PolygonSet2& pieces) {
  // A non-finite coordinate has no exact value: the area is NaN, which fails every
  // comparison (rather than ending the process inside the rational arithmetic).
  auto finite = [](const Loop2& loop) {
    return std::all_of(loop.begin(), loop.end(),
                       [](const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
  };
  for (const PolygonWithHoles2& polygon : pieces) {
    if (!finite(polygon.outer) ||
        !std::all_of(polygon.holes.begin(), polygon.holes.end(), finite)) {
      return std::nan("");
    }
  }
  auto twice_area = [](const Loop2& loop) {
    CGAL::Exact_rational sum = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& p = loop[i];
      const Point2& q = loop[next_index(i, loop.size())];
      sum += CGAL::Exact_rational(p.x) * CGAL::Exact_rational(q.y);
      sum -= CGAL::Exact_rational(p.y) * CGAL::Exact_rational(q.x);
    }
    return CGAL::abs(sum);
  };
  CGAL::Exact_rational total = 0;
  for (const PolygonWithHoles2& polygon : pieces) {
    total += twice_area(polygon.outer);
    for (const Loop2& hole : polygon.holes) total -= twice_area(hole);
  }
  return CGAL::to_double(total / 2);
}

std::string validity_problem(const PolygonWithHoles2& polygon, Contacts rule) {
  return polygon_problem(polygon, "", rule);
}

std::string validity_problem(const PolygonSet2& polygons, Contacts rule) {
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (std::string problem =
            polygon_problem(polygons[i], "polygon " + std::to_string(i) + ": ", rule);
        !problem.empty()) {
      return problem;
    }
  }
  if (polygons.size() < 2) return {};
  std::vector<NamedLoop> loops;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    std::vector<NamedLoop> own =
        named_loops(polygons[i], "polygon " + std::to_string(i) + " ", static_cast<int>(i));
    loops.insert(loops.end(), own.begin(), own.end());
  }
  ContactCheck contacts{loops, false, true, {}, {}, {}};
  contacts.run();
  if (!contacts.problem.empty()) return contacts.problem;
  std::vector<Box> boxes;
  boxes.reserve(polygons.size());
  for (const PolygonWithHoles2& polygon : polygons) boxes.push_back(box_of(polygon.outer));
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    for (std::size_t j = i + 1; j < polygons.size(); ++j) {
      if (!boxes_meet(boxes[i], boxes[j])) continue;
      if (lies_in_area_of(polygons[j], polygons[i]) || lies_in_area_of(polygons[i], polygons[j])) {
        return "polygons " + std::to_string(i) + " and " + std::to_string(j) + " overlap";
      }
    }
  }
  return {};
}

PolygonSet2 oriented(const PolygonSet2& polygons) {
  auto turn = [](Loop2& loop, CGAL::Orientation wanted) {
    CGAL::Exact_rational twice_area = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& p = loop[i];
      const Point2& q = loop[next_index(i, loop.size())];
      twice_area += CGAL::Exact_rational(p.x) * CGAL::Exact_rational(q.y);
      twice_area -= CGAL::Exact_rational(p.y) * CGAL::Exact_rational(q.x);
    }
    const CGAL::Sign sign = CGAL::sign(twice_area);
    if (sign != CGAL::ZERO && static_cast<int>(sign) != static_cast<int>(wanted)) {
      std::reverse(loop.begin(), loop.end());
    }
  };
  PolygonSet2 result = polygons;
  for (PolygonWithHoles2& polygon : result) {
    turn(polygon.outer, CGAL::COUNTERCLOCKWISE);
    for (Loop2& hole : polygon.holes) turn(hole, CGAL::CLOCKWISE);
  }
  return result;
}

std::string input_problem(const PolygonSet2& operand) {
  return validity_problem(oriented(without_repeats(operand)), Contacts::kAnyPoint);
}

bool cgal_accepts(const PolygonWithHoles2& polygon) {
  using Traits = CGAL::Gps_segment_traits_2<Kernel>;
  auto convert = [](const Loop2& loop) {
    ExactPolygon result;
    for (const Point2& p : loop) result.push_back(ExactPoint(p.x, p.y));
    return result;
  };
  // Degenerate edges and non-finite numbers would break CGAL's preconditions.
  auto unusable = [](const Loop2& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      if (loop[i] == loop[next_index(i, loop.size())]) return true;
      if (!std::isfinite(loop[i].x) || !std::isfinite(loop[i].y)) return true;
    }
    return loop.size() < 3;
  };
  if (unusable(polygon.outer)) return false;
  std::vector<ExactPolygon> holes;
  for (const Loop2& hole : polygon.holes) {
    if (unusable(hole)) return false;
    holes.push_back(convert(hole));
  }
  const ExactPolygonWithHoles exact(convert(polygon.outer), holes.begin(), holes.end());
  Traits traits;
  return CGAL::is_valid_polygon_with_holes(exact, traits);
}

namespace {

// One set holding the union of all regions: their polygons joined in one go (CGAL
// joins a range by divide and conquer, far faster than one region at a time).
ExactPolygonSet exact_union(std::span<const PolygonSet2> regions) {
  PolygonSet2 all;
  for (const PolygonSet2& region : regions) all.insert(all.end(), region.begin(), region.end());
  return to_exact_set(all);
}

}  // namespace

double exact_union_area(std::span<const PolygonSet2> regions) {
  return to_double(exact_area_of(exact_union(regions)));
}

ExactUnionComparison compare_exact_unions(std::span<const PolygonSet2> a,
                                          std::span<const PolygonSet2> b) {
  const ExactPolygonSet a_union = exact_union(a);
  const ExactPolygonSet b_union = exact_union(b);
  ExactPolygonSet difference = a_union;
  difference.symmetric_difference(b_union);
  ExactUnionComparison result;
  result.a_union = to_double(exact_area_of(a_union));
  result.b_union = to_double(exact_area_of(b_union));
  result.symmetric_difference = to_double(exact_area_of(difference));
  return result;
}

bool near_exact_crossing(const Point2& p, const Point2& a0, const Point2& a1, const Point2& b0,
                         const Point2& b1, double relative) {
  const Kernel::Line_2 a(ExactPoint(a0.x, a0.y), ExactPoint(a1.x, a1.y));
  const Kernel::Line_2 b(ExactPoint(b0.x, b0.y), ExactPoint(b1.x, b1.y));
  const auto meet = CGAL::intersection(a, b);
  const ExactPoint* at = meet ? boost::get<ExactPoint>(&*meet) : nullptr;
  if (at == nullptr) return false;
  const ExactNumber r(relative);
  return CGAL::abs(ExactNumber(p.x) - at->x()) <= r * CGAL::abs(at->x()) &&
         CGAL::abs(ExactNumber(p.y) - at->y()) <= r * CGAL::abs(at->y());
}

bool exact_triangles_share_more_than(const std::array<glm::dvec3, 3>& a,
                                     const std::array<glm::dvec3, 3>& b,
                                     std::span<const glm::dvec3> common) {
  using Point3 = Kernel::Point_3;
  auto point = [](const glm::dvec3& p) { return Point3(p.x, p.y, p.z); };
  const Kernel::Triangle_3 ta(point(a[0]), point(a[1]), point(a[2]));
  const Kernel::Triangle_3 tb(point(b[0]), point(b[1]), point(b[2]));
  const auto meet = CGAL::intersection(ta, tb);
  if (!meet) return false;
  auto is_common = [&](const Point3& p) {
    return std::any_of(common.begin(), common.end(),
                       [&](const glm::dvec3& c) { return p == point(c); });
  };
  if (const Point3* p = boost::get<Point3>(&*meet)) return !is_common(*p);
  if (const Kernel::Segment_3* s = boost::get<Kernel::Segment_3>(&*meet)) {
    return !(common.size() == 2 && is_common(s->source()) && is_common(s->target()));
  }
  return true;  // a triangle or a polygon of the plane they share
}

}  // namespace shadowgen::test
