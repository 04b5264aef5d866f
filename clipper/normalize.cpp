#include "clipper/normalize.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "clipper/predicates.h"

namespace shadowgen::clipper {

namespace {

// True when prev -> v -> next turns straight back at v (v is not between its neighbours).
bool is_spike(const Point2& prev, const Point2& v, const Point2& next) {
  if (orient2d(prev, v, next) != Orientation::kCollinear) return false;
  return (prev.x - v.x) * (next.x - v.x) + (prev.y - v.y) * (next.y - v.y) >= 0.0;
}

// One pass with a stack: a vertex is dropped when it repeats its predecessor, or when
// `redundant` says so of it and its neighbours. Dropping one can make its predecessor
// removable, hence the stack and the final wrap-around.
template <typename Redundant>
bool clean(Loop2& loop, Redundant redundant) {
  // Nothing to drop, the usual case, is seen without copying: the pass below tests the
  // same triples, every vertex with its neighbours around the ring.
  const std::size_t count = loop.size();
  if (count >= 3) {
    bool clean_already = true;
    for (std::size_t i = 0; i < count && clean_already; ++i) {
      const Point2& prev = loop[i == 0 ? count - 1 : i - 1];
      const Point2& next = loop[i + 1 == count ? 0 : i + 1];
      clean_already = loop[i] != next && !redundant(prev, loop[i], next);
    }
    if (clean_already) return true;
  }
  bool changed = true;
  while (changed && loop.size() >= 3) {
    changed = false;
    Loop2 kept;
    kept.reserve(loop.size());
    for (const Point2& p : loop) {
      if (!kept.empty() && kept.back() == p) {
        changed = true;
        continue;
      }
      while (kept.size() >= 2 && redundant(kept[kept.size() - 2], kept.back(), p)) {
        kept.pop_back();
        changed = true;
      }
      kept.push_back(p);
    }
    // Close the ring: the seam vertices get the same test.
    while (kept.size() >= 3) {
      const std::size_t n = kept.size();
      if (redundant(kept[n - 2], kept[n - 1], kept[0])) {
        kept.pop_back();
        changed = true;
      } else if (redundant(kept[n - 1], kept[0], kept[1])) {
        kept.erase(kept.begin());
        changed = true;
      } else {
        break;
      }
    }
    loop.swap(kept);
  }
  if (loop.size() < 3) {
    loop.clear();
    return false;
  }
  return true;
}

}  // namespace

bool clean_loop(Loop2& loop) {
  return clean(loop, [](const Point2& prev, const Point2& v, const Point2& next) {
    return prev == v || v == next || orient2d(prev, v, next) == Orientation::kCollinear;
  });
}

bool remove_spikes(Loop2& loop) {
  if (!clean(loop, [](const Point2& prev, const Point2& v, const Point2& next) {
        return prev == v || v == next || is_spike(prev, v, next);
      })) {
    return false;
  }
  // Still all on one line: no area.
  for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    if (orient2d(loop[i], loop[j], loop[j + 1 == n ? 0 : j + 1]) != Orientation::kCollinear) {
      return true;
    }
  }
  loop.clear();
  return false;
}

bool is_counter_clockwise(const Loop2& loop) {
  // Edges run once each way (bridges) bound nothing: cancel them. Every direction along
  // the edges left, from their lowest endpoint, points into one half-plane; the loop may
  // pass that point more than once, and the first direction clockwise from straight down
  // is an edge out of the point exactly when the loop runs counter-clockwise.
  const std::size_t n = loop.size();
  const auto lowest = std::min_element(loop.begin(), loop.end());
  if (std::count(loop.begin(), loop.end(), *lowest) == 1) {
    // Passed once: no bridge ends there, and the turn there tells (the usual case).
    const std::size_t i = static_cast<std::size_t>(lowest - loop.begin());
    return orient2d(loop[i == 0 ? n - 1 : i - 1], loop[i], loop[i + 1 == n ? 0 : i + 1]) ==
           Orientation::kCounterClockwise;
  }
  std::map<std::pair<Point2, Point2>, int> net;  // undirected edge (low, high): +1 low -> high
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[i + 1 == n ? 0 : i + 1];
    if (a == b) continue;
    if (a < b)
      ++net[{a, b}];
    else
      --net[{b, a}];
  }
  const Point2* p = nullptr;
  for (const auto& [e, k] : net) {
    if (k != 0 && (p == nullptr || e.first < *p)) p = &e.first;
  }
  if (p == nullptr) return false;
  const Point2 low = *p;
  std::vector<std::pair<Point2, bool>> rays;
  for (const auto& [e, k] : net) {
    if (k != 0 && e.first == low) rays.push_back({e.second, k > 0});
    if (k != 0 && e.second == low) rays.push_back({e.first, k < 0});
  }
  const std::pair<Point2, bool>* first = &rays[0];
  for (const auto& r : rays) {
    if (orient2d(low, r.first, first->first) == Orientation::kCounterClockwise) first = &r;
  }
  return first->second;
}

bool encloses_counter_clockwise(const Loop2& loop) {
  // Twice the signed area, Σ x_i y_{i+1} - x_{i+1} y_i, in plain floating point: each of
  // the 2n products and 2n - 1 additions rounds by at most u = 2^-53 relative, so the sum
  // is within (2n + 1) u (1 + small) of Σ |products| of the exact one, plus 2n half
  // subnormals where products underflow. Doubling that bound covers the higher-order
  // terms with room to spare.
  const std::size_t n = loop.size();
  double sum = 0.0;
  double magnitude = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = loop[i];
    const Point2& b = loop[i + 1 == n ? 0 : i + 1];
    const double left = a.x * b.y;
    const double right = b.x * a.y;
    sum += left - right;
    magnitude += std::abs(left) + std::abs(right);
  }
  const double bound =
      static_cast<double>(2 * n + 1) * 0x1p-52 * magnitude + static_cast<double>(2 * n) * 0x1p-1074;
  if (std::isfinite(magnitude) && std::abs(sum) > bound) return sum > 0.0;
  return is_counter_clockwise(loop);
}

namespace {

void append_normalized(const PolygonWithHoles2& p, PolygonSet2& out) {
  PolygonWithHoles2 q;
  q.outer = p.outer;
  if (!clean_loop(q.outer)) return;
  if (!encloses_counter_clockwise(q.outer)) std::reverse(q.outer.begin(), q.outer.end());
  q.holes.reserve(p.holes.size());
  for (const Loop2& h : p.holes) {
    Loop2 hole = h;
    if (!clean_loop(hole)) continue;
    if (encloses_counter_clockwise(hole)) std::reverse(hole.begin(), hole.end());
    q.holes.push_back(std::move(hole));
  }
  out.push_back(std::move(q));
}

}  // namespace

PolygonSet2 normalized(const PolygonSet2& polygons) {
  PolygonSet2 out;
  out.reserve(polygons.size());
  for (const PolygonWithHoles2& p : polygons) append_normalized(p, out);
  return out;
}

PolygonSet2 normalized_polygon(const PolygonWithHoles2& polygon) {
  PolygonSet2 out;
  out.reserve(1);
  append_normalized(polygon, out);
  return out;
}

}  // namespace shadowgen::clipper
