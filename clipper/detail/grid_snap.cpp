#include "grid_snap.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <tuple>

#include "clipper/predicates.h"
#include "close_pairs.h"
#include "crossing.h"
#include "loop_of_routes.h"
#include "snap_contacts.h"

namespace shadowgen::clipper::detail {
namespace {

struct Cell {
  std::int64_t x, y;
  friend bool operator==(const Cell&, const Cell&) = default;
  friend bool operator<(const Cell& a, const Cell& b) {
    return std::tie(a.x, a.y) < std::tie(b.x, b.y);
  }
};

struct Edge {
  Point2 from, to;
};

// The smallest power of two of at least 8u·m, and never below the least normal double.
double grid_width(double magnitude) {
  const double t = 0x1p-50 * magnitude;
  if (!(t > std::numeric_limits<double>::min())) return std::numeric_limits<double>::min();
  int e = 0;
  const double m = std::frexp(t, &e);
  return m == 0.5 ? t : std::ldexp(1.0, e);
}

class Grid {
 public:
  explicit Grid(double width) : g_(width) {}

  // The cell of v along one axis: v / g is exact (g a power of two), and v lies in cell i
  // when i − ½ ≤ v / g < i + ½.
  std::int64_t index(double v) const {
    const double q = v / g_;
    const double f = std::floor(q);
    return static_cast<std::int64_t>(f) + (q >= f + 0.5 ? 1 : 0);
  }
  Cell cell(const Point2& p) const { return {index(p.x), index(p.y)}; }
  Point2 centre(const Cell& c) const {
    return {static_cast<double>(c.x) * g_, static_cast<double>(c.y) * g_};
  }

  // Whether the edge a-b (a ≠ b) meets the half-open cell c = [x0, x1) × [y0, y1): for a
  // small enough ε > 0, whether it meets the closed square [x0, x1 − ε] × [y0, y1 − ε],
  // which holds every point of c but those within ε of its upper and right sides. Their
  // boxes overlap, and its line does not pass with all four corners strictly on one side
  // (the separating axes of a segment and a square). A corner moved by ε lies on the side
  // of the line that the first nonzero term of its orientation gives: (b − a) × (−ε, 0)
  // = Δy·ε, (b − a) × (0, −ε) = −Δx·ε, (b − a) × (−ε, −ε) = (Δy − Δx)·ε, each sign exact.
  bool meets(const Point2& a, const Point2& b, const Cell& c) const {
    const Point2 centre_point = centre(c);
    const double h = 0.5 * g_;
    const double x0 = centre_point.x - h, x1 = centre_point.x + h;
    const double y0 = centre_point.y - h, y1 = centre_point.y + h;
    if (std::max(a.x, b.x) < x0 || std::min(a.x, b.x) >= x1) return false;
    if (std::max(a.y, b.y) < y0 || std::min(a.y, b.y) >= y1) return false;
    const double dx = b.x - a.x, dy = b.y - a.y;
    auto sign = [](double v) { return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0); };
    auto side = [&](double x, double y, int moved) {
      const int exact = static_cast<int>(orient2d(a, b, Point2{x, y}));
      return exact != 0 ? exact : moved;
    };
    const int corners[4] = {side(x0, y0, 0), side(x1, y0, sign(dy)), side(x0, y1, sign(-dx)),
                            side(x1, y1, dot_sign(a, b, {0.0, 0.0}, {-1.0, 1.0}))};
    if (corners[0] == 0) return true;
    for (const int s : corners) {
      if (s != corners[0]) return true;
    }
    return false;
  }

 private:
  double g_;
};

// The hot cells (sorted, each once) whose indices lie in the box of cells spanned by
// a and b, in order along a -> b, that `take` accepts.
template <typename Take>
std::vector<Cell> cells_along(const std::vector<Cell>& hot, const Cell& a, const Cell& b,
                              Take take) {
  const std::int64_t x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
  const std::int64_t y0 = std::min(a.y, b.y), y1 = std::max(a.y, b.y);
  std::vector<Cell> found;
  for (auto it = std::lower_bound(hot.begin(), hot.end(),
                                  Cell{x0, std::numeric_limits<std::int64_t>::min()});
       it != hot.end() && it->x <= x1; ++it) {
    if (it->y >= y0 && it->y <= y1 && take(*it)) found.push_back(*it);
  }
  // The cells a segment meets come in an order in which both indices change
  // monotonically (the cells partition the plane, and its coordinates do): so ordered by
  // the indices, each in the segment's own direction.
  const std::int64_t sx = b.x >= a.x ? 1 : -1, sy = b.y >= a.y ? 1 : -1;
  std::sort(found.begin(), found.end(), [sx, sy](const Cell& p, const Cell& q) {
    return std::make_pair(sx * p.x, sy * p.y) < std::make_pair(sx * q.x, sy * q.y);
  });
  return found;
}

// Snaps the loops listed in `members` ({side, loop}) on the grid of their largest
// magnitude.
void snap_group(std::vector<Loop2> (&loops)[2],
                const std::vector<std::pair<int, std::size_t>>& members) {
  double magnitude = 0.0;
  std::vector<Edge> edges;
  for (const auto& [side, index] : members) {
    const Loop2& loop = loops[side][index];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& p = loop[i];
      magnitude = std::max({magnitude, std::fabs(p.x), std::fabs(p.y)});
      const Point2& q = loop[i + 1 == loop.size() ? 0 : i + 1];
      if (p != q) edges.push_back({p, q});
    }
  }
  const Grid grid(grid_width(magnitude));
  std::vector<Cell> hot;
  for (const Edge& e : edges) hot.push_back(grid.cell(e.from));
  for_each_close_pair(
      edges, [](std::size_t) { return 0.0; }, [](std::size_t) { return true; },
      [&](std::size_t i, std::size_t j) {
        const Edge& a = edges[i];
        const Edge& b = edges[j];
        if (!properly_cross(a.from, a.to, b.from, b.to)) return;
        // Within 5u of each coordinate's magnitude of the exact crossing (crossing.h);
        // 8u covers that and the rounding of the bounds themselves.
        const Point2 at = crossing_point(a.from, a.to, b.from, b.to);
        const double rx = 0x1p-50 * std::fabs(at.x), ry = 0x1p-50 * std::fabs(at.y);
        const Cell low = grid.cell({at.x - rx, at.y - ry});
        const Cell high = grid.cell({at.x + rx, at.y + ry});
        for (std::int64_t x = low.x; x <= high.x; ++x) {
          for (std::int64_t y = low.y; y <= high.y; ++y) hot.push_back({x, y});
        }
      });
  std::sort(hot.begin(), hot.end());
  hot.erase(std::unique(hot.begin(), hot.end()), hot.end());

  for (const auto& [side, index] : members) {
    Loop2& loop = loops[side][index];
    LoopOfRoutes out(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2& a = loop[i];
      const Point2& b = loop[i + 1 == loop.size() ? 0 : i + 1];
      const Cell start = grid.cell(a);
      if (a == b) {
        out.add(grid.centre(start));
        continue;
      }
      const std::vector<Cell> route =
          cells_along(hot, start, grid.cell(b), [&](const Cell& c) { return grid.meets(a, b, c); });
      // A centre lying exactly inside a fragment between two centres the edge passes
      // becomes a vertex of it: the fragment runs through that point.
      for (std::size_t k = 0; k < route.size(); ++k) {
        const Point2 from = grid.centre(route[k]);
        out.add(from);
        if (k + 1 == route.size()) break;
        const Point2 to = grid.centre(route[k + 1]);
        for (const Cell& c : cells_along(hot, route[k], route[k + 1], [&](const Cell& c) {
               const Point2 p = grid.centre(c);
               return p != from && p != to && on_segment(from, to, p);
             })) {
          out.add(grid.centre(c));
        }
      }
    }
    loop = out.take();
  }
}

}  // namespace

void snap_round_on_grid(std::vector<Loop2> (&loops)[2]) {
  // Loops whose boxes, grown by the widest grid any of them can get, meet: snapped on
  // one grid, since their edges may meet; the others cannot meet them after snapping
  // (a vertex moves less than a grid's width).
  struct LoopBox {
    Point2 from, to;  // the box's corners, as close_pairs.h reads an edge
    int side;
    std::size_t index;
  };
  std::vector<LoopBox> boxes;
  double magnitude = 0.0;
  for (int side = 0; side < 2; ++side) {
    for (std::size_t index = 0; index < loops[side].size(); ++index) {
      const Loop2& loop = loops[side][index];
      if (loop.empty()) continue;
      Point2 low = loop[0], high = loop[0];
      for (const Point2& p : loop) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
        magnitude = std::max({magnitude, std::fabs(p.x), std::fabs(p.y)});
      }
      boxes.push_back({low, high, side, index});
    }
  }
  const double reach = grid_width(magnitude);
  std::vector<std::size_t> parent(boxes.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto root = [&parent](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for_each_close_pair(
      boxes, [reach](std::size_t) { return reach; }, [](std::size_t) { return true; },
      [&](std::size_t i, std::size_t j) { parent[root(i)] = root(j); });
  std::vector<std::vector<std::pair<int, std::size_t>>> groups(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    groups[root(i)].emplace_back(boxes[i].side, boxes[i].index);
  }
  for (const auto& members : groups) {
    if (!members.empty()) snap_group(loops, members);
  }
}

}  // namespace shadowgen::clipper::detail
