// The shadow oracle's only translation unit with CGAL (see shadow_oracle.h for the
// construction). 3D constructions are done in CGAL's exact rationals (the exact number
// type behind Epeck); 2D regions are Epeck polygon sets in each part's chart.

#include "tests/shadowgen/shadows/shadow_oracle.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <type_traits>
#include <utility>

namespace shadowgen::test {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Q = std::decay_t<decltype(CGAL::exact(std::declval<FT>()))>;
using Point2 = Kernel::Point_2;
using Polygon2 = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;

struct V3 {
  Q x, y, z;
  const Q& operator[](int a) const { return a == 0 ? x : (a == 1 ? y : z); }
};

V3 exact(const glm::dvec3& p) { return {Q(p.x), Q(p.y), Q(p.z)}; }
V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(const V3& a, const Q& t) { return {a.x * t, a.y * t, a.z * t}; }
Q dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(const V3& a, const V3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
bool is_zero(const V3& a) { return CGAL::is_zero(a.x) && CGAL::is_zero(a.y) && CGAL::is_zero(a.z); }
double to_double(const Q& q) { return CGAL::to_double(q); }

// A part's exact plane n·p = c and its chart (coordinates i, j kept, k dropped).
struct ExactPlane {
  V3 n;
  Q c;
  int k = 2, i = 0, j = 1;
  double area_factor = 1.0;  // |n| / |n_k|: 3D area per unit of chart area
  bool degenerate = true;

  Q side(const V3& p) const { return dot(n, p) - c; }
  std::pair<Q, Q> chart(const V3& p) const { return {p[i], p[j]}; }
  V3 lift(const Q& a, const Q& b) const {
    const Q third = (c - n[i] * a - n[j] * b) / n[k];
    std::array<Q, 3> out;
    out[static_cast<std::size_t>(i)] = a;
    out[static_cast<std::size_t>(j)] = b;
    out[static_cast<std::size_t>(k)] = third;
    return {out[0], out[1], out[2]};
  }
};

ExactPlane plane_of(const std::vector<V3>& outer) {
  ExactPlane plane;
  V3 n{Q(0), Q(0), Q(0)};
  for (std::size_t m = 0; m < outer.size(); ++m) {
    n = n + cross(outer[m], outer[(m + 1) % outer.size()]);
  }
  plane.n = n;
  if (is_zero(n)) return plane;
  plane.degenerate = false;
  Q sum(0);
  for (const V3& v : outer) sum += dot(n, v);
  plane.c = sum / Q(static_cast<int>(outer.size()));
  const Q ax = CGAL::abs(n.x), ay = CGAL::abs(n.y), az = CGAL::abs(n.z);
  plane.k = (az >= ax && az >= ay) ? 2 : (ay >= ax ? 1 : 0);
  plane.i = (plane.k + 1) % 3;
  plane.j = (plane.k + 2) % 3;
  const double nx = to_double(n.x), ny = to_double(n.y), nz = to_double(n.z);
  plane.area_factor = std::sqrt(nx * nx + ny * ny + nz * nz) / std::fabs(to_double(n[plane.k]));
  return plane;
}

Point2 point2(const std::pair<Q, Q>& p) { return Point2(FT(p.first), FT(p.second)); }

// A loop as a CGAL polygon turned counter-clockwise, repeated consecutive vertices
// dropped; nothing when no area is left.
std::optional<Polygon2> ccw_polygon(std::vector<Point2> points) {
  points.erase(std::unique(points.begin(), points.end()), points.end());
  while (points.size() > 1 && points.front() == points.back()) points.pop_back();
  if (points.size() < 3) return std::nullopt;
  Polygon2 polygon(points.begin(), points.end());
  const CGAL::Sign sign = CGAL::sign(polygon.area());
  if (sign == CGAL::ZERO) return std::nullopt;
  if (sign == CGAL::NEGATIVE) polygon.reverse_orientation();
  return polygon;
}

// Outer loop minus the holes: robust to holes touching the outer loop anywhere, which
// CGAL's Polygon_with_holes_2 does not allow. Every loop must be simple.
PolygonSet region(const Polygon2& outer, const std::vector<Polygon2>& holes) {
  PolygonSet set;
  set.insert(outer);
  if (!holes.empty()) {
    PolygonSet removed;
    removed.join(holes.begin(), holes.end());
    set.difference(removed);
  }
  return set;
}

Q chart_area(const PolygonSet& set) {
  std::vector<PolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  FT total = 0;
  for (const PolygonWithHoles& part : parts) {
    total += part.outer_boundary().area();
    for (auto h = part.holes_begin(); h != part.holes_end(); ++h) total += h->area();
  }
  return CGAL::exact(total);
}

struct Box2 {
  Q xmin, xmax, ymin, ymax;
};

struct Part {
  std::size_t face = 0;
  std::vector<std::vector<V3>> loops;  // outer first
  ExactPlane plane;
  PolygonSet region;  // in the chart
  Q chart_area{0};
  std::optional<Box2> box;  // of the chart outer loop
};

std::vector<Point2> chart_points(const std::vector<V3>& loop, const ExactPlane& plane) {
  std::vector<Point2> out;
  out.reserve(loop.size());
  for (const V3& v : loop) out.push_back(point2(plane.chart(v)));
  return out;
}

Part make_part(std::size_t face, const hsr::Polygon3& polygon) {
  Part part;
  part.face = face;
  auto add = [&part](const hsr::Loop3& loop) {
    std::vector<V3> out;
    out.reserve(loop.size());
    for (const glm::dvec3& v : loop) out.push_back(exact(v));
    part.loops.push_back(std::move(out));
  };
  add(polygon.outer);
  for (const hsr::Loop3& h : polygon.holes) add(h);
  part.plane = plane_of(part.loops[0]);
  if (part.plane.degenerate) return part;
  std::optional<Polygon2> outer = ccw_polygon(chart_points(part.loops[0], part.plane));
  if (!outer) {
    part.plane.degenerate = true;
    return part;
  }
  std::vector<Polygon2> holes;
  for (std::size_t h = 1; h < part.loops.size(); ++h) {
    if (auto p = ccw_polygon(chart_points(part.loops[h], part.plane))) holes.push_back(*p);
  }
  part.region = region(*outer, holes);
  part.chart_area = chart_area(part.region);
  if (CGAL::is_zero(part.chart_area)) {
    part.plane.degenerate = true;
    return part;
  }
  Box2 box{Q(0), Q(0), Q(0), Q(0)};
  bool first = true;
  for (const V3& v : part.loops[0]) {
    const auto [a, b] = part.plane.chart(v);
    if (first || a < box.xmin) box.xmin = a;
    if (first || a > box.xmax) box.xmax = a;
    if (first || b < box.ymin) box.ymin = b;
    if (first || b > box.ymax) box.ymax = b;
    first = false;
  }
  part.box = box;
  return part;
}

// Squared distance from p to the segment ab.
Q squared_distance_to_segment(const V3& p, const V3& a, const V3& b) {
  const V3 ab = b - a;
  const Q len2 = dot(ab, ab);
  Q t(0);
  if (!CGAL::is_zero(len2)) {
    t = dot(p - a, ab) / len2;
    if (t < Q(0)) t = Q(0);
    if (t > Q(1)) t = Q(1);
  }
  const V3 d = p - (a + ab * t);
  return dot(d, d);
}

// Squared distance from p to the part's region (outer minus holes).
Q squared_distance_to_part(const V3& p, const Part& part) {
  const ExactPlane& plane = part.plane;
  const Q nn = dot(plane.n, plane.n);
  const Q s = plane.side(p);
  const V3 foot = p - plane.n * (s / nn);
  std::vector<PolygonWithHoles> pieces;
  part.region.polygons_with_holes(std::back_inserter(pieces));
  const Point2 q = point2(plane.chart(foot));
  for (const PolygonWithHoles& piece : pieces) {
    if (piece.outer_boundary().bounded_side(q) == CGAL::ON_UNBOUNDED_SIDE) continue;
    bool in_hole = false;
    for (auto h = piece.holes_begin(); h != piece.holes_end(); ++h) {
      if (h->bounded_side(q) == CGAL::ON_BOUNDED_SIDE) in_hole = true;
    }
    if (!in_hole) return s * s / nn;
  }
  std::optional<Q> best;
  for (const std::vector<V3>& loop : part.loops) {
    for (std::size_t m = 0; m < loop.size(); ++m) {
      Q d = squared_distance_to_segment(p, loop[m], loop[(m + 1) % loop.size()]);
      if (!best || d < *best) best = d;
    }
  }
  return *best;
}

// a·x + b·y + e >= 0 in a chart.
struct HalfPlane {
  Q a, b, e;
  Q eval(const std::pair<Q, Q>& p) const { return a * p.first + b * p.second + e; }
};

// The 3D half-space m·q + e0 >= 0 restricted to a plane, in that plane's chart.
HalfPlane restrict_to(const V3& m, const Q& e0, const ExactPlane& plane) {
  const Q& nk = plane.n[plane.k];
  const Q& mk = m[plane.k];
  return {m[plane.i] - mk * plane.n[plane.i] / nk, m[plane.j] - mk * plane.n[plane.j] / nk,
          e0 + mk * plane.c / nk};
}

// Sutherland–Hodgman on a convex polygon, exact.
std::vector<std::pair<Q, Q>> clip_convex(const std::vector<std::pair<Q, Q>>& polygon,
                                         const HalfPlane& h) {
  std::vector<std::pair<Q, Q>> out;
  const std::size_t n = polygon.size();
  for (std::size_t m = 0; m < n; ++m) {
    const auto& p = polygon[m];
    const auto& q = polygon[(m + 1) % n];
    const Q fp = h.eval(p), fq = h.eval(q);
    if (fp >= Q(0)) out.push_back(p);
    if ((fp > Q(0) && fq < Q(0)) || (fp < Q(0) && fq > Q(0))) {
      const Q t = fp / (fp - fq);
      out.emplace_back(p.first + (q.first - p.first) * t, p.second + (q.second - p.second) * t);
    }
  }
  return out;
}

// Where a loop that is not simple touches or crosses itself, for messages.
std::string self_contact(const std::vector<Point2>& loop) {
  const std::size_t n = loop.size();
  auto at = [&loop](std::size_t m) {
    std::ostringstream out;
    out.precision(17);
    out << "vertex " << m << " (" << CGAL::to_double(loop[m].x()) << ' '
        << CGAL::to_double(loop[m].y()) << ')';
    return out.str();
  };
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (loop[a] == loop[b]) return at(a) + " repeats at " + std::to_string(b);
    }
  }
  for (std::size_t a = 0; a < n; ++a) {
    const Kernel::Segment_2 ea(loop[a], loop[(a + 1) % n]);
    for (std::size_t b = a + 1; b < n; ++b) {
      const Kernel::Segment_2 eb(loop[b], loop[(b + 1) % n]);
      const bool adjacent = b == a + 1 || (a == 0 && b == n - 1);
      if (adjacent) {
        const std::size_t shared = b == a + 1 ? b : a;
        const Point2& before = loop[(shared + n - 1) % n];
        const Point2& after = loop[(shared + 1) % n];
        if (CGAL::collinear(before, loop[shared], after) &&
            !CGAL::collinear_are_ordered_along_line(before, loop[shared], after)) {
          return at(shared) + " is a spike";
        }
        continue;
      }
      if (CGAL::do_intersect(ea, eb)) {
        return "edges from " + at(a) + " and " + at(b) + " meet (loop of " + std::to_string(n) +
               ")";
      }
    }
  }
  return "unknown";
}

// The exact lit region of one (part, light), in the part's chart.
struct PartLit {
  PolygonSet lit;
  Q chart_area{0};
};

struct ShadowPiece {
  Polygon2 outer;
  std::vector<Polygon2> holes;
};

}  // namespace

struct ShadowOracle::Impl {
  Scene scene;
  std::vector<Part> parts;
  std::vector<std::vector<std::size_t>> parts_of_face;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<PartLit>> cache;

  std::map<std::size_t, std::vector<bool>> beyond_range;  // by light, per face

  const std::vector<PartLit>& lit(std::size_t face, std::size_t light);
  const std::vector<bool>& dropped(std::size_t light);
  PartLit lit_part(const Part& f, const Light& light, const std::vector<bool>& dropped) const;
};

// Faces wholly beyond the light's range.end: exact squared distances.
const std::vector<bool>& ShadowOracle::Impl::dropped(std::size_t light) {
  if (auto it = beyond_range.find(light); it != beyond_range.end()) return it->second;
  const Light& l = scene.lights.at(light);
  std::vector<bool> out(scene.faces.size(), false);
  if (l.type == LightType::kPoint && l.range) {
    const V3 p = exact(l.position);
    const Q end(l.range->end);
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      bool beyond = true;
      for (std::size_t index : parts_of_face[f]) {
        const Part& part = parts[index];
        if (part.plane.degenerate) continue;
        if (!(squared_distance_to_part(p, part) > end * end)) beyond = false;
      }
      out[f] = beyond;
    }
  }
  return beyond_range.emplace(light, std::move(out)).first->second;
}

PartLit ShadowOracle::Impl::lit_part(const Part& f, const Light& light,
                                     const std::vector<bool>& dropped) const {
  PartLit result;
  if (f.plane.degenerate || dropped[f.face]) return result;
  const ExactPlane& fp = f.plane;
  const bool point = light.type == LightType::kPoint;
  const V3 position = exact(light.position);
  const V3 direction = exact(light.direction);
  // Facing: s_F(light) > 0 for a point light, n·d < 0 for a directional one.
  const Q s_light = point ? fp.side(position) : Q(0);
  const Q n_dot_d = point ? Q(0) : dot(fp.n, direction);
  if (point ? !(s_light > Q(0)) : !(n_dot_d < Q(0))) return result;

  // The cone from a point light over F's chart box (widened), as inward half-spaces.
  std::vector<std::pair<V3, Q>> cone;  // m, e0: m·q + e0 >= 0
  if (point) {
    const Box2& b = *f.box;
    const Q w = (b.xmax - b.xmin) + (b.ymax - b.ymin) + Q(1);
    const std::array<std::pair<Q, Q>, 4> corners = {
        std::pair<Q, Q>{b.xmin - w, b.ymin - w}, std::pair<Q, Q>{b.xmax + w, b.ymin - w},
        std::pair<Q, Q>{b.xmax + w, b.ymax + w}, std::pair<Q, Q>{b.xmin - w, b.ymax + w}};
    std::array<V3, 4> r;
    for (std::size_t m = 0; m < 4; ++m) r[m] = fp.lift(corners[m].first, corners[m].second);
    for (std::size_t m = 0; m < 4; ++m) {
      V3 normal = cross(r[m] - position, r[(m + 1) % 4] - position);
      if (dot(normal, r[(m + 2) % 4] - position) < Q(0)) normal = normal * Q(-1);
      cone.emplace_back(normal, -dot(normal, position));
    }
  }

  auto project = [&](const V3& q) -> std::pair<Q, Q> {
    const Q s = fp.side(q);
    if (point) {
      const Q t = s_light / (s_light - s);
      return fp.chart(position + (q - position) * t);
    }
    return fp.chart(q - direction * (s / n_dot_d));
  };

  std::vector<Polygon2> simple_shadows;
  PolygonSet shadow;
  auto add_piece = [&](const std::vector<std::vector<std::pair<Q, Q>>>& loops) {
    std::vector<Point2> outer_points;
    for (const auto& p : loops[0]) outer_points.push_back(point2(p));
    std::optional<Polygon2> outer = ccw_polygon(std::move(outer_points));
    if (!outer) return;
    std::vector<Polygon2> holes;
    for (std::size_t h = 1; h < loops.size(); ++h) {
      std::vector<Point2> hole_points;
      for (const auto& p : loops[h]) hole_points.push_back(point2(p));
      if (auto hole = ccw_polygon(std::move(hole_points))) holes.push_back(*hole);
    }
    if (holes.empty()) {
      simple_shadows.push_back(std::move(*outer));
    } else {
      shadow.join(region(*outer, holes));
    }
  };

  // Every other part occludes, also one beyond the light's range.end: the range only
  // drops receivers, never the shadows on a face that reaches inside it.
  for (const Part& o : parts) {
    if (&o == &f || o.plane.degenerate) continue;
    const ExactPlane& op = o.plane;
    // A light in O's plane: O is edge-on to it and blocks nothing.
    if (point ? CGAL::is_zero(op.side(position)) : CGAL::is_zero(dot(op.n, direction))) continue;
    bool coplanar = true, any_front = false, any_behind = false, any_beyond = false;
    std::vector<bool> outside_cone(cone.size(), true);
    for (const std::vector<V3>& loop : o.loops) {
      for (const V3& v : loop) {
        const Q s = fp.side(v);
        if (!CGAL::is_zero(s)) coplanar = false;
        if (s > Q(0)) any_front = true;
        if (s < Q(0)) any_behind = true;
        if (point && s >= s_light) any_beyond = true;
        for (std::size_t c = 0; c < cone.size(); ++c) {
          if (!(dot(cone[c].first, v) + cone[c].second < Q(0))) outside_cone[c] = false;
        }
      }
    }
    if (coplanar || !any_front) continue;
    if (std::any_of(outside_cone.begin(), outside_cone.end(), [](bool b) { return b; })) continue;

    if (!any_behind && !any_beyond) {
      // Wholly within the closed slab (and off the light's parallel plane): project the
      // loops as they are.
      std::vector<std::vector<std::pair<Q, Q>>> loops;
      for (const std::vector<V3>& loop : o.loops) {
        std::vector<std::pair<Q, Q>> image;
        image.reserve(loop.size());
        for (const V3& v : loop) image.push_back(project(v));
        loops.push_back(std::move(image));
      }
      add_piece(loops);
      continue;
    }

    // Cut O exactly in its own chart: s_F >= 0, and for a point light the cone.
    std::vector<HalfPlane> cuts;
    cuts.push_back(restrict_to(fp.n, -fp.c, op));
    for (const auto& [m, e0] : cone) cuts.push_back(restrict_to(m, e0, op));
    const Box2& ob = *o.box;
    const Q w = (ob.xmax - ob.xmin) + (ob.ymax - ob.ymin) + Q(1);
    std::vector<std::pair<Q, Q>> window = {{ob.xmin - w, ob.ymin - w},
                                           {ob.xmax + w, ob.ymin - w},
                                           {ob.xmax + w, ob.ymax + w},
                                           {ob.xmin - w, ob.ymax + w}};
    for (const HalfPlane& h : cuts) {
      window = clip_convex(window, h);
      if (window.size() < 3) break;
    }
    if (window.size() < 3) continue;
    std::vector<Point2> window_points;
    for (const auto& p : window) window_points.push_back(point2(p));
    std::optional<Polygon2> window_polygon = ccw_polygon(std::move(window_points));
    if (!window_polygon) continue;
    PolygonSet kept = o.region;
    kept.intersection(*window_polygon);
    std::vector<PolygonWithHoles> pieces;
    kept.polygons_with_holes(std::back_inserter(pieces));
    for (const PolygonWithHoles& piece : pieces) {
      auto image = [&](const Polygon2& loop) {
        std::vector<std::pair<Q, Q>> out;
        for (auto v = loop.vertices_begin(); v != loop.vertices_end(); ++v) {
          out.push_back(project(op.lift(CGAL::exact(v->x()), CGAL::exact(v->y()))));
        }
        return out;
      };
      std::vector<std::vector<std::pair<Q, Q>>> loops{image(piece.outer_boundary())};
      for (auto h = piece.holes_begin(); h != piece.holes_end(); ++h) loops.push_back(image(*h));
      add_piece(loops);
    }
  }
  if (!simple_shadows.empty()) shadow.join(simple_shadows.begin(), simple_shadows.end());
  result.lit = f.region;
  result.lit.difference(shadow);
  result.chart_area = chart_area(result.lit);
  return result;
}

const std::vector<PartLit>& ShadowOracle::Impl::lit(std::size_t face, std::size_t light) {
  const auto key = std::make_pair(face, light);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  const Light& l = scene.lights.at(light);
  const std::vector<bool>& gone = dropped(light);
  std::vector<PartLit> out;
  for (std::size_t index : parts_of_face.at(face)) out.push_back(lit_part(parts[index], l, gone));
  return cache.emplace(key, std::move(out)).first->second;
}

ShadowOracle::ShadowOracle(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->scene = scene;
  impl_->parts_of_face.resize(scene.faces.size());
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (const hsr::Polygon3& p : scene.faces[f].parts) {
      impl_->parts_of_face[f].push_back(impl_->parts.size());
      impl_->parts.push_back(make_part(f, p));
    }
  }
}

ShadowOracle::~ShadowOracle() = default;

ExactLit ShadowOracle::lit(std::size_t face, std::size_t light) const {
  const std::vector<PartLit>& lit = impl_->lit(face, light);
  const std::vector<std::size_t>& mine = impl_->parts_of_face.at(face);
  ExactLit out;
  // The fraction exactly when the face has one chart; else from the rounded areas.
  Q face_chart(0), lit_chart(0);
  for (std::size_t m = 0; m < mine.size(); ++m) {
    const Part& part = impl_->parts[mine[m]];
    if (part.plane.degenerate) continue;
    out.face_area += to_double(part.chart_area) * part.plane.area_factor;
    out.lit_area += to_double(lit[m].chart_area) * part.plane.area_factor;
    face_chart += part.chart_area;
    lit_chart += lit[m].chart_area;
  }
  if (mine.size() == 1 && !CGAL::is_zero(face_chart)) {
    out.lit_fraction = to_double(lit_chart / face_chart);
  } else if (out.face_area > 0.0) {
    out.lit_fraction = out.lit_area / out.face_area;
  }
  return out;
}

LitComparison ShadowOracle::compare(std::size_t face, std::size_t light,
                                    std::span<const hsr::Polygon3> ours) const {
  const std::vector<PartLit>& lit = impl_->lit(face, light);
  const std::vector<std::size_t>& mine = impl_->parts_of_face.at(face);
  const ExactLit areas = this->lit(face, light);
  LitComparison out;
  out.face_area = areas.face_area;
  out.exact_lit_area = areas.lit_area;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto fail = [&](std::string why) {
    out.problem = std::move(why);
    out.our_union_area = out.our_pieces_area = out.symmetric_difference = nan;
    out.outside_face_area = nan;
    return out;
  };

  std::vector<PolygonSet> our_sets(mine.size());
  std::vector<Q> pieces_chart(mine.size(), Q(0));
  for (std::size_t p = 0; p < ours.size(); ++p) {
    const hsr::Polygon3& polygon = ours[p];
    // The part whose plane the polygon lies closest to (relative to |n|).
    std::optional<std::size_t> best;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < mine.size(); ++m) {
      const Part& part = impl_->parts[mine[m]];
      if (part.plane.degenerate) continue;
      double worst = 0.0;
      const double norm = std::sqrt(to_double(dot(part.plane.n, part.plane.n)));
      for (const glm::dvec3& v : polygon.outer) {
        worst = std::max(worst, std::fabs(to_double(part.plane.side(exact(v)))) / norm);
      }
      if (worst < best_distance) {
        best_distance = worst;
        best = m;
      }
    }
    if (!best) return fail("lit polygon " + std::to_string(p) + " on a face without area");
    const ExactPlane& plane = impl_->parts[mine[*best]].plane;
    // Parts exactly in that plane (a face whose holes cut its region apart has several)
    // are one chart: the polygon goes to the one it overlaps most, below.
    std::vector<std::size_t> coplanar;
    for (std::size_t m = 0; m < mine.size(); ++m) {
      const Part& part = impl_->parts[mine[m]];
      if (!part.plane.degenerate && is_zero(cross(part.plane.n, plane.n)) &&
          CGAL::is_zero(plane.side(part.loops[0][0]))) {
        coplanar.push_back(m);
      }
    }
    auto to_chart = [&plane](const hsr::Loop3& loop) {
      std::vector<Point2> out_points;
      out_points.reserve(loop.size());
      for (const glm::dvec3& v : loop) out_points.emplace_back(v[plane.i], v[plane.j]);
      return out_points;
    };
    // A loop that is not simple is read by the even-odd rule (the exclusive or of the
    // triangles fanning out from its first vertex), so its region can still be measured;
    // the first such loop is reported in `invalid`.
    auto loop_region = [&](const hsr::Loop3& loop, const std::string& name) -> PolygonSet {
      std::vector<Point2> points = to_chart(loop);
      points.erase(std::unique(points.begin(), points.end()), points.end());
      while (points.size() > 1 && points.front() == points.back()) points.pop_back();
      PolygonSet set;
      if (points.size() < 3) return set;  // no area
      const Polygon2 polygon2(points.begin(), points.end());
      if (polygon2.is_simple()) {
        if (auto ccw = ccw_polygon(points)) set.insert(*ccw);
        return set;
      }
      if (out.invalid.empty()) {
        out.invalid = "lit polygon " + std::to_string(p) + ": " + name + " not simple (" +
                      self_contact(points) + ")";
      }
      for (std::size_t m = 1; m + 1 < points.size(); ++m) {
        if (auto triangle = ccw_polygon({points[0], points[m], points[m + 1]})) {
          set.symmetric_difference(PolygonSet(*triangle));
        }
      }
      return set;
    };
    PolygonSet piece = loop_region(polygon.outer, "outer loop");
    if (piece.is_empty()) continue;
    if (!polygon.holes.empty()) {
      PolygonSet removed;
      for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
        removed.join(loop_region(polygon.holes[h], "hole " + std::to_string(h)));
      }
      piece.difference(removed);
    }
    if (coplanar.size() > 1) {
      Q most(-1);
      for (const std::size_t m : coplanar) {
        PolygonSet common = piece;
        common.intersection(impl_->parts[mine[m]].region);
        if (const Q overlap = chart_area(common); overlap > most) {
          most = overlap;
          best = m;
        }
      }
    }
    pieces_chart[*best] += chart_area(piece);
    our_sets[*best].join(piece);
  }
  for (std::size_t m = 0; m < mine.size(); ++m) {
    const Part& part = impl_->parts[mine[m]];
    if (part.plane.degenerate) continue;
    const double factor = part.plane.area_factor;
    out.our_union_area += to_double(chart_area(our_sets[m])) * factor;
    out.our_pieces_area += to_double(pieces_chart[m]) * factor;
    PolygonSet difference = our_sets[m];
    difference.symmetric_difference(lit[m].lit);
    out.symmetric_difference += to_double(chart_area(difference)) * factor;
    PolygonSet outside = our_sets[m];
    outside.difference(part.region);
    out.outside_face_area += to_double(chart_area(outside)) * factor;
  }
  return out;
}

std::vector<hsr::Polygon3> ShadowOracle::lit_polygons(std::size_t face, std::size_t light) const {
  const std::vector<PartLit>& lit = impl_->lit(face, light);
  const std::vector<std::size_t>& mine = impl_->parts_of_face.at(face);
  std::vector<hsr::Polygon3> out;
  for (std::size_t m = 0; m < mine.size(); ++m) {
    const ExactPlane& plane = impl_->parts[mine[m]].plane;
    std::vector<PolygonWithHoles> pieces;
    lit[m].lit.polygons_with_holes(std::back_inserter(pieces));
    auto lifted = [&plane](const Polygon2& loop) {
      hsr::Loop3 out_loop;
      for (auto v = loop.vertices_begin(); v != loop.vertices_end(); ++v) {
        const V3 p = plane.lift(CGAL::exact(v->x()), CGAL::exact(v->y()));
        out_loop.emplace_back(to_double(p.x), to_double(p.y), to_double(p.z));
      }
      return out_loop;
    };
    for (const PolygonWithHoles& piece : pieces) {
      hsr::Polygon3 polygon{lifted(piece.outer_boundary()), {}};
      for (auto h = piece.holes_begin(); h != piece.holes_end(); ++h) {
        polygon.holes.push_back(lifted(*h));
      }
      out.push_back(std::move(polygon));
    }
  }
  return out;
}

}  // namespace shadowgen::test
