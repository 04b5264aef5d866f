#include "tests/support/random_polygons.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "tests/support/cgal_oracle.h"

namespace shadowgen::test {
namespace {

using clipper::Point2;

double uniform(std::mt19937_64& rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(rng);
}

int uniform_int(std::mt19937_64& rng, int low, int high) {
  return std::uniform_int_distribution<int>(low, high)(rng);
}

bool coin(std::mt19937_64& rng, double probability) {
  return std::bernoulli_distribution(probability)(rng);
}

// Shoelace in doubles: exact enough to tell the orientation of the loops built here
// (small integers, or loops far from degenerate).
double shoelace(const Loop2& loop) {
  double twice = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Point2& p = loop[i];
    const Point2& q = loop[(i + 1) % loop.size()];
    twice += p.x * q.y - p.y * q.x;
  }
  return twice / 2.0;
}

// Vertices at strictly increasing angles, one in each of n equal sectors and at least a
// fifth of a sector apart, so the loop is star-shaped around the centre: every edge
// spans less than pi. Counter-clockwise.
Loop2 star_loop(std::mt19937_64& rng, Point2 centre, int n, double radius, double min_fraction) {
  const double sector = 2.0 * std::numbers::pi / n;
  const double start = uniform(rng, 0.0, sector);
  Loop2 loop;
  loop.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double angle = start + (i + uniform(rng, 0.1, 0.9)) * sector;
    const double r = radius * uniform(rng, min_fraction, 1.0);
    loop.push_back({centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)});
  }
  return loop;
}

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// Crossing-number test in doubles: only used with a margin far above rounding.
bool inside_loop(Point2 p, const Loop2& loop) {
  bool inside = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Point2& a = loop[i];
    const Point2& b = loop[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

double distance_to_loop(Point2 p, const Loop2& loop) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    best = std::min(best, distance_to_segment(p, loop[i], loop[(i + 1) % loop.size()]));
  }
  return best;
}

// --- grid polygons ---------------------------------------------------------------------

Loop2 snapped_star(std::mt19937_64& rng, Point2 centre, int n, double radius) {
  Loop2 loop;
  for (const Point2& p : star_loop(rng, centre, n, radius, 0.4)) {
    const Point2 q{std::clamp(std::round(p.x), 0.0, double{kGridSize}),
                   std::clamp(std::round(p.y), 0.0, double{kGridSize})};
    if (loop.empty() || !(q == loop.back())) loop.push_back(q);
  }
  while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
  return loop;
}

std::optional<PolygonWithHoles2> snapped_star_polygon(std::mt19937_64& rng) {
  PolygonWithHoles2 polygon;
  const Point2 centre{double(uniform_int(rng, 3, 9)), double(uniform_int(rng, 3, 9))};
  polygon.outer = snapped_star(rng, centre, uniform_int(rng, 4, 9), uniform(rng, 2.5, 6.5));
  if (polygon.outer.size() < 3 || shoelace(polygon.outer) <= 0.0) return std::nullopt;
  if (!validity_problem(polygon).empty()) return std::nullopt;
  const int holes = uniform_int(rng, 0, 2);
  for (int h = 0; h < holes; ++h) {
    for (int attempt = 0; attempt < 5; ++attempt) {
      const Point2 hole_centre{double(uniform_int(rng, 1, kGridSize - 1)),
                               double(uniform_int(rng, 1, kGridSize - 1))};
      Loop2 hole = snapped_star(rng, hole_centre, uniform_int(rng, 3, 5), uniform(rng, 1.0, 2.5));
      if (hole.size() < 3 || shoelace(hole) <= 0.0) continue;
      std::reverse(hole.begin(), hole.end());
      polygon.holes.push_back(std::move(hole));
      if (validity_problem(polygon).empty()) break;
      polygon.holes.pop_back();
    }
  }
  return polygon;
}

using Cell = std::pair<int, int>;

bool in_grid(const Cell& c) {
  return c.first >= 0 && c.first < kGridSize && c.second >= 0 && c.second < kGridSize;
}

// Two cells meeting only at a corner would make the boundary touch itself.
bool has_pinch(const std::set<Cell>& cells) {
  for (int i = 0; i <= kGridSize; ++i) {
    for (int j = 0; j <= kGridSize; ++j) {
      const bool a = cells.count({i - 1, j - 1}) > 0;
      const bool b = cells.count({i, j - 1}) > 0;
      const bool c = cells.count({i - 1, j}) > 0;
      const bool d = cells.count({i, j}) > 0;
      if ((a && d && !b && !c) || (b && c && !a && !d)) return true;
    }
  }
  return false;
}

bool is_connected(const std::set<Cell>& cells) {
  if (cells.empty()) return false;
  std::set<Cell> seen{*cells.begin()};
  std::vector<Cell> stack{*cells.begin()};
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    for (const Cell& n : {Cell{i + 1, j}, Cell{i - 1, j}, Cell{i, j + 1}, Cell{i, j - 1}}) {
      if (cells.count(n) > 0 && seen.insert(n).second) stack.push_back(n);
    }
  }
  return seen.size() == cells.size();
}

// Boundary of a pinch-free polyomino: unit edges with the cells on their left, so the
// outer loop runs counter-clockwise and holes clockwise; every grid point starts at most
// one boundary edge, so the loops trace without choices.
std::vector<Loop2> polyomino_boundary(const std::set<Cell>& cells, bool merge_collinear) {
  std::map<Point2, Point2> next;
  for (const auto& [i, j] : cells) {
    const double x = i;
    const double y = j;
    if (cells.count({i, j - 1}) == 0) next[{x, y}] = {x + 1, y};
    if (cells.count({i + 1, j}) == 0) next[{x + 1, y}] = {x + 1, y + 1};
    if (cells.count({i, j + 1}) == 0) next[{x + 1, y + 1}] = {x, y + 1};
    if (cells.count({i - 1, j}) == 0) next[{x, y + 1}] = {x, y};
  }
  std::vector<Loop2> loops;
  while (!next.empty()) {
    Loop2 loop;
    Point2 p = next.begin()->first;
    while (next.count(p) > 0) {
      loop.push_back(p);
      const Point2 q = next[p];
      next.erase(p);
      p = q;
    }
    if (merge_collinear) {
      Loop2 merged;
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const Point2& a = loop[(k + loop.size() - 1) % loop.size()];
        const Point2& b = loop[k];
        const Point2& c = loop[(k + 1) % loop.size()];
        if ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) != 0.0) merged.push_back(b);
      }
      loop = std::move(merged);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::optional<PolygonWithHoles2> polyomino_polygon(std::mt19937_64& rng) {
  // Grown from a cell near the middle, so that two polyominoes usually overlap.
  std::set<Cell> cells{{uniform_int(rng, 3, kGridSize - 4), uniform_int(rng, 3, kGridSize - 4)}};
  const int target = uniform_int(rng, 6, 45);
  std::vector<Cell> frontier(cells.begin(), cells.end());
  for (int guard = 0; static_cast<int>(cells.size()) < target && guard < 1000; ++guard) {
    const Cell& from =
        frontier[std::uniform_int_distribution<std::size_t>(0, frontier.size() - 1)(rng)];
    static constexpr std::array<Cell, 4> kSteps{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
    const Cell step = kSteps[static_cast<std::size_t>(uniform_int(rng, 0, 3))];
    const Cell cell{from.first + step.first, from.second + step.second};
    if (in_grid(cell) && cells.insert(cell).second) frontier.push_back(cell);
  }
  // Carve holes: remove cells whose eight neighbours are all present (sometimes two
  // side by side); the checks below reject anything that pinches or disconnects.
  const int carvings = coin(rng, 0.6) ? uniform_int(rng, 1, 3) : 0;
  for (int c = 0; c < carvings; ++c) {
    std::vector<Cell> candidates;
    for (const auto& [i, j] : cells) {
      bool surrounded = true;
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) surrounded &= cells.count({i + di, j + dj}) > 0;
      }
      if (surrounded) candidates.push_back({i, j});
    }
    if (candidates.empty()) break;
    const Cell hole =
        candidates[std::uniform_int_distribution<std::size_t>(0, candidates.size() - 1)(rng)];
    cells.erase(hole);
    if (coin(rng, 0.3)) cells.erase({hole.first + 1, hole.second});
  }
  if (has_pinch(cells) || !is_connected(cells)) return std::nullopt;
  std::vector<Loop2> loops = polyomino_boundary(cells, !coin(rng, 0.25));
  PolygonWithHoles2 polygon;
  for (Loop2& loop : loops) {
    if (shoelace(loop) > 0.0) {
      if (!polygon.outer.empty()) return std::nullopt;
      polygon.outer = std::move(loop);
    } else {
      polygon.holes.push_back(std::move(loop));
    }
  }
  if (polygon.outer.empty() || !validity_problem(polygon).empty()) return std::nullopt;
  return polygon;
}

}  // namespace

void randomize_loops(PolygonWithHoles2& polygon, std::mt19937_64& rng) {
  auto shuffle = [&rng](Loop2& loop) {
    if (coin(rng, 0.5)) std::reverse(loop.begin(), loop.end());
    const auto shift = std::uniform_int_distribution<std::size_t>(0, loop.size() - 1)(rng);
    std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(shift), loop.end());
  };
  shuffle(polygon.outer);
  for (Loop2& hole : polygon.holes) shuffle(hole);
}

PolygonWithHoles2 random_polygon_with_holes(std::mt19937_64& rng) {
  for (;;) {
    PolygonWithHoles2 polygon;
    const Point2 centre{uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5)};
    const double radius = uniform(rng, 0.6, 1.2);
    polygon.outer = star_loop(rng, centre, uniform_int(rng, 5, 16), radius, 0.35);
    struct Disk {
      Point2 centre;
      double radius;
    };
    std::vector<Disk> disks;
    const int holes = uniform_int(rng, 1, 3);
    for (int attempt = 0; attempt < 40 && static_cast<int>(disks.size()) < holes; ++attempt) {
      const double angle = uniform(rng, 0.0, 2.0 * std::numbers::pi);
      const double offset = uniform(rng, 0.0, 0.7 * radius);
      const Point2 c{centre.x + offset * std::cos(angle), centre.y + offset * std::sin(angle)};
      if (!inside_loop(c, polygon.outer)) continue;
      const double room = std::min(0.8 * distance_to_loop(c, polygon.outer), 0.4 * radius);
      if (room < 0.05 * radius) continue;
      bool apart = true;
      for (const Disk& d : disks) {
        apart &= std::hypot(c.x - d.centre.x, c.y - d.centre.y) > room + d.radius + 0.01 * radius;
      }
      if (!apart) continue;
      disks.push_back({c, room});
      Loop2 hole = star_loop(rng, c, uniform_int(rng, 3, 8), room, 0.4);
      std::reverse(hole.begin(), hole.end());
      polygon.holes.push_back(std::move(hole));
    }
    if (polygon.holes.empty() || !validity_problem(polygon).empty()) continue;
    randomize_loops(polygon, rng);
    return polygon;
  }
}

PolygonWithHoles2 random_grid_polygon(std::mt19937_64& rng) {
  for (;;) {
    std::optional<PolygonWithHoles2> polygon =
        coin(rng, 0.5) ? polyomino_polygon(rng) : snapped_star_polygon(rng);
    if (!polygon) continue;
    randomize_loops(*polygon, rng);
    return *polygon;
  }
}

PolygonWithHoles2 sliver_triangle(std::mt19937_64& rng, double aspect) {
  const double angle = uniform(rng, 0.0, 2.0 * std::numbers::pi);
  const double length = uniform(rng, 1.0, 2.0);
  const Point2 middle{uniform(rng, -0.2, 0.2), uniform(rng, -0.2, 0.2)};
  const Point2 direction{std::cos(angle), std::sin(angle)};
  const Point2 a{middle.x - 0.5 * length * direction.x, middle.y - 0.5 * length * direction.y};
  const Point2 b{middle.x + 0.5 * length * direction.x, middle.y + 0.5 * length * direction.y};
  const double t = uniform(rng, -0.3, 0.3) * length;
  const double height = aspect * length;
  const Point2 apex{middle.x + t * direction.x - height * direction.y,
                    middle.y + t * direction.y + height * direction.x};
  PolygonWithHoles2 polygon{{a, b, apex}, {}};
  randomize_loops(polygon, rng);
  return polygon;
}

Loop2 almost_concurrent_star(std::mt19937_64& rng, int lines) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Loop2 star;
  for (int k = 0; k < lines; ++k) {
    const double angle = unit(rng) * std::numbers::pi, radius = 1.0 + 0.5 * unit(rng);
    const double hair = 1e-13 * unit(rng);
    const double dx = radius * std::cos(angle), dy = radius * std::sin(angle);
    star.push_back({1000.0 + dx + hair, 1000.0 + dy - hair});
    star.push_back({1000.0 - dx + hair, 1000.0 - dy + hair});
  }
  return star;
}

}  // namespace shadowgen::test
