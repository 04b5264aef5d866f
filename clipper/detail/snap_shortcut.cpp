// Snap rounding's shortcut: the operands shown clear of each other but where edges cross
// properly or a vertex lies in an edge's way, in doubles with stated bounds, and the
// edges routed through those points.

#include "snap_shortcut.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "box_masks.h"
#include "crossing.h"
#include "loop_of_routes.h"
#include "snap.h"
#include "snap_contacts.h"
#include "snap_convergence.h"

namespace shadowgen::clipper::detail {
namespace {

// The common case decided without rounds: operands of a few edges that meet only where
// edges cross properly or where a vertex lies in an edge's way (on it, or off it within
// the vertex's pixel: an edge that a cut shared with an earlier clip, a T-junction), every
// other point well clear of every edge. The rounds would route each edge through the
// points found on it, in order along it, and then find nothing more: every other contact
// they look for (points in each other's pixels, a point in the way of an edge or of a
// piece moved by a rounded crossing or a vertex, pieces crossing anew) needs a point
// within a pixel plus a piece's deviation (two pixels at most) of an edge or of another
// point, and here every point lies more than kClearPixels of the widest pixel of the
// operands from each edge and point it is not routed through or on. Returns false,
// leaving the loops as they came, where that is not shown; snap_round then runs the
// rounds, which give the same loops wherever this gives any
// (SnapRound.TheShortcutGivesWhatTheRoundsGive).
constexpr std::size_t kShortcutEdges = 128;
constexpr double kClearPixels = 8.0;

// Whether p lies off the line through a and b by more than `reach`, in doubles with a
// generous bound (8u of the products' magnitudes) on the rounding of the determinant
// taken off.
bool off_line(const Point2& p, const Point2& a, const Point2& b, double reach) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double left = dx * (p.y - a.y), right = dy * (p.x - a.x);
  const double rounding = 0x1p-50 * (std::fabs(left) + std::fabs(right));
  return std::fabs(left - right) - rounding > 1.001 * reach * std::sqrt(dx * dx + dy * dy);
}

// Whether the rounds' first look routes the whole edge a-b through vertex v: v lies in
// the edge's box grown by its margin (ContactFinder's candidate test) and the edge passes
// through v's pixel. A line further from v than twice the pixel's half width misses the
// pixel (whose corners, rounded, lie within 1.1 half widths of v in each coordinate):
// that common answer is given in doubles, before the exact look at the four corners.
bool in_way(const Point2& v, const Point2& a, const Point2& b) {
  const double margin = 1.25 * std::max(snap_distance(a), snap_distance(b));
  return v.x >= std::min(a.x, b.x) - margin && v.x <= std::max(a.x, b.x) + margin &&
         v.y >= std::min(a.y, b.y) - margin && v.y <= std::max(a.y, b.y) + margin &&
         !off_line(v, a, b, 2.0 * snap_distance(v)) && within_snap_distance(v, a, b);
}

bool apart(const Point2& p, const Point2& q, double reach) {
  return std::fabs(p.x - q.x) > reach || std::fabs(p.y - q.y) > reach;
}

}  // namespace

bool snap_round_separated(std::vector<Loop2> (&loops)[2], SnapRoundingStats* stats) {
  struct Edge {
    Point2 from, to;
    double xmin, xmax, ymin, ymax;  // the box, grown by the reach
    std::uint32_t next;             // the edge leaving `to`, in the same loop
  };
  // A point an edge is to be routed through.
  struct RoutePoint {
    std::uint32_t edge;
    Point2 at;
  };
  // Kept from call to call: a clip of small polygons would otherwise spend much of its
  // time allocating them.
  thread_local std::vector<Edge> edges;
  thread_local std::vector<RoutePoint> through;
  edges.clear();
  through.clear();
  double magnitude = 0.0;
  for (const auto& side : loops) {
    for (const Loop2& loop : side) {
      if (edges.size() + loop.size() > kShortcutEdges) return false;
      const auto first = static_cast<std::uint32_t>(edges.size());
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Point2& p = loop[i];
        const std::size_t next = i + 1 == loop.size() ? 0 : i + 1;
        edges.push_back({p, loop[next], 0, 0, 0, 0, first + static_cast<std::uint32_t>(next)});
        magnitude = std::max({magnitude, std::fabs(p.x), std::fabs(p.y)});
      }
    }
  }
  const double reach = kClearPixels * snap_distance({magnitude, magnitude});
  // At most kShortcutEdges edges: every pair is looked at, boxes first (a sweep's sorting
  // cost more than it saved at these sizes). The vertices and boxes are also laid out
  // coordinate by coordinate, so that a box is tested against all of them at once.
  const std::size_t n = edges.size();
  MaskLane vx, vy, bx0, bx1, by0, by1;
  for (std::size_t k = 0; k < n; ++k) {
    Edge& e = edges[k];
    e.xmin = std::min(e.from.x, e.to.x) - reach;
    e.xmax = std::max(e.from.x, e.to.x) + reach;
    e.ymin = std::min(e.from.y, e.to.y) - reach;
    e.ymax = std::max(e.from.y, e.to.y) + reach;
    vx[k] = e.from.x;
    vy[k] = e.from.y;
    bx0[k] = e.xmin;
    bx1[k] = e.xmax;
    by0[k] = e.ymin;
    by1[k] = e.ymax;
  }
  for (MaskLane* lane : {&vx, &vy, &bx0, &bx1, &by0, &by1}) lane->pad(n);
  static_assert(kShortcutEdges <= MaskLane::kCapacity, "a lane for every edge");
  std::size_t splits = 0;
  // Vertices: apart from one another, and each clear of every edge or in its way between
  // its ends (then found there by both edges the vertex ends). Every vertex starts an
  // edge, and a point within the reach of it lies in that edge's grown box. An edge's
  // own ends are not looked at from it: its end is the next edge's start, whose test
  // against this edge's start (in the next edge's box when they are not apart) tells.
  for (std::uint32_t m = 0; m < n; ++m) {
    const Edge& e = edges[m];
    const bool clear =
        each_box_meeting(vx, vx, vy, vy, 0, n, e.xmin, e.xmax, e.ymin, e.ymax, [&](std::size_t k) {
          if (k == m || k == e.next) return true;
          const Point2& v = edges[k].from;
          if (v == e.from) return true;
          if (!apart(v, e.from, reach)) return false;
          if (v == e.to || off_line(v, e.from, e.to, reach)) return true;
          if (!in_way(v, e.from, e.to) || !apart(v, e.to, reach)) return false;
          through.push_back({m, v});
          splits += 2;
          return true;
        });
    if (!clear) return false;
  }
  // Proper crossings, rounded: apart from every vertex and clear of every edge but their
  // own two. Each pair once: the boxes after this one's, but for the next edge's, which
  // shares an end with it.
  std::size_t crossings = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Edge& a = edges[i];
    const bool clear = each_box_meeting(
        bx0, bx1, by0, by1, i + 1, n, a.xmin, a.xmax, a.ymin, a.ymax, [&](std::size_t k) {
          if (k == a.next) return true;
          const auto j = static_cast<std::uint32_t>(k);
          const Edge& b = edges[j];
          if (a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to) return true;
          if (!properly_cross(a.from, a.to, b.from, b.to)) return true;
          // A vertex of one in the other's way (a hair across it): routed through, not
          // crossed.
          if (in_way(a.from, b.from, b.to) || in_way(a.to, b.from, b.to) ||
              in_way(b.from, a.from, a.to) || in_way(b.to, a.from, a.to)) {
            return true;
          }
          const Point2 at = crossing_point(a.from, a.to, b.from, b.to);
          // The edges whose grown boxes hold the crossing.
          const bool at_clear = each_box_meeting(
              bx0, bx1, by0, by1, 0, n, at.x, at.x, at.y, at.y, [&](std::size_t m) {
                const Edge& e = edges[m];
                if (!apart(at, e.from, reach)) return false;
                return m == i || m == j || off_line(at, e.from, e.to, reach);
              });
          if (!at_clear) return false;
          through.push_back({i, at});
          through.push_back({j, at});
          ++crossings;
          splits += 2;
          return true;
        });
    if (!clear) return false;
  }
  if (!through.empty() && snap_round_limit() < 1) return false;
  std::sort(through.begin(), through.end(), [](const RoutePoint& a, const RoutePoint& b) {
    if (a.edge != b.edge) return a.edge < b.edge;
    return AlongSegment(edges[a.edge].from, edges[a.edge].to)(a.at, b.at);
  });
  std::size_t k = 0, next = 0;
  for (auto& side : loops) {
    for (Loop2& loop : side) {
      LoopOfRoutes out(loop.size() + through.size());
      for (std::size_t i = 0; i < loop.size(); ++i, ++k) {
        out.add(edges[k].from);
        for (; next < through.size() && through[next].edge == k; ++next) out.add(through[next].at);
      }
      loop = out.take();
    }
  }
  if (stats != nullptr) {
    *stats = {};
    stats->crossings = crossings;
    stats->splits = splits;
    stats->rounds = through.empty() ? 0 : 1;
    stats->separated = true;
  }
  return true;
}

}  // namespace shadowgen::clipper::detail
