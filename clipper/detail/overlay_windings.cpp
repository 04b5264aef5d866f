// The overlay graph's windings spread: around each vertex from sector to sector, over
// each connected part from its seed, and the parts located against each other.

#include "overlay_windings.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>

#include "clipper/box.h"
#include "clipper/predicates.h"
#include "point_location.h"

namespace shadowgen::clipper::detail {
namespace {

using Boundary = std::vector<Loop2>;

// The windings of the sectors around v, from those left of the edge from_edge: turning
// counter-clockwise, each next edge is crossed from its right to its left.
void spread_around(OverlayGraph& g, std::uint32_t v, std::uint32_t from_edge,
                   std::vector<std::uint32_t>& todo) {
  const std::span<std::uint32_t> at = g.edges_at(v);
  const std::size_t k = at.size();
  const std::size_t start =
      static_cast<std::size_t>(std::find(at.begin(), at.end(), from_edge) - at.begin());
  Winding left = left_of_outward(g.edges[from_edge], v);
  std::size_t next = start;
  for (std::size_t step = 1; step < k; ++step) {
    next = next + 1 == k ? 0 : next + 1;
    OverlayEdge& e = g.edges[at[next]];
    left = left + outward_multiplicity(e, v);
    if (e.known) continue;
    e.right = e.lo == v ? left - e.multiplicity : left;
    e.known = true;
    todo.push_back(far_end(e, v));
    todo.push_back(at[next]);
  }
}

// The winding numbers of the other parts' loops around each part's seed (which lies on
// none of them: parts share no vertex and, the graph being noded, no point). A loop winds
// around no point outside its box, so the seeds are swept in x order past the loops
// whose boxes span their x: about the square root of the loops at a time for blocks
// spread over a ground, where testing every loop for every seed grew with the square of
// the parts. Winding numbers are sums of integers: the order changes nothing.
std::vector<Winding> windings_outside_parts(const Boundary (&loops_in)[2], const OverlayGraph& g,
                                            const std::vector<std::uint32_t>& seeds) {
  struct LoopRef {
    Box2 box;
    std::uint32_t part;
    int operand;
    std::uint32_t loop;
  };
  std::vector<LoopRef> loops;
  for (int s = 0; s < 2; ++s) {
    for (std::size_t l = 0; l < loops_in[s].size(); ++l) {
      if (g.ids[s][l].empty()) continue;
      loops.push_back(
          {box_of(loops_in[s][l]), g.part[g.ids[s][l].front()], s, static_cast<std::uint32_t>(l)});
    }
  }
  std::sort(loops.begin(), loops.end(),
            [](const LoopRef& a, const LoopRef& b) { return a.box.xmin < b.box.xmin; });
  std::vector<std::uint32_t> order(seeds.size());
  for (std::uint32_t part = 0; part < seeds.size(); ++part) order[part] = part;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return g.index.point(seeds[a]).x < g.index.point(seeds[b]).x;
  });
  std::vector<Winding> out(seeds.size(), Winding{});
  std::vector<const LoopRef*> active;
  std::size_t next = 0;
  for (const std::uint32_t part : order) {
    const Point2& p = g.index.point(seeds[part]);
    for (; next < loops.size() && loops[next].box.xmin <= p.x; ++next) {
      active.push_back(&loops[next]);
    }
    std::size_t kept = 0;
    for (const LoopRef* loop : active) {
      if (loop->box.xmax < p.x) continue;  // left behind: the seeds come in x order
      active[kept++] = loop;
      if (loop->part == part || !loop->box.contains(p)) continue;
      add_winding_number(p, loops_in[loop->operand][loop->loop], out[part][loop->operand]);
    }
    active.resize(kept);
  }
  return out;
}

// Spreads the windings over the part of `seed`, its lowest-leftmost vertex, whose
// outside (the sector straight left of it) has the windings `outside`.
void spread_part(OverlayGraph& g, std::uint32_t seed, const Winding& outside) {
  const std::span<std::uint32_t> at = g.edges_at(seed);
  if (at.empty()) return;
  // Every edge of the seed runs to the right of it, or straight up: the sector left of
  // the one turned furthest counter-clockwise contains the direction straight left,
  // outside all of the part's loops.
  const Point2& p = g.index.point(seed);
  std::uint32_t top = at.front();
  for (const std::uint32_t e : at) {
    if (orient2d(p, g.index.point(far_end(g.edges[top], seed)),
                 g.index.point(far_end(g.edges[e], seed))) == Orientation::kCounterClockwise) {
      top = e;
    }
  }
  OverlayEdge& first = g.edges[top];
  first.right = first.lo == seed ? outside - first.multiplicity : outside;
  first.known = true;
  std::vector<char>& done = g.done;
  std::vector<std::uint32_t>& todo = g.todo;  // pairs: a vertex, and an edge known
  todo.assign({seed, top, far_end(first, seed), top});
  while (!todo.empty()) {
    const std::uint32_t e = todo.back();
    todo.pop_back();
    const std::uint32_t v = todo.back();
    todo.pop_back();
    if (done[v]) continue;
    done[v] = 1;
    spread_around(g, v, e, todo);
  }
}

}  // namespace

void spread_windings(const std::vector<Loop2> (&loops)[2], OverlayGraph& g) {
  const std::size_t count = g.index.size();
  std::vector<char>& done = g.done;
  done.assign(count, 0);
  if (count == 0) return;
  // Most overlays are one connected part. The lowest-leftmost vertex of all lies outside
  // every loop, so the spreading starts there with no winding; only where it leaves
  // vertices unreached are the parts found and located against each other. (Where two
  // distinct points compare equal, a zero of either sign, the parts are found too, as
  // they pick their seeds.)
  std::uint32_t lowest = 0;
  bool tie = false;
  for (std::uint32_t v = 1; v < count; ++v) {
    const Point2& p = g.index.point(v);
    const Point2& q = g.index.point(lowest);
    if (p < q) {
      lowest = v;
      tie = false;
    } else if (!(q < p)) {
      tie = true;
    }
  }
  if (!tie) {
    spread_part(g, lowest, Winding{});
    if (std::find(done.begin(), done.end(), 0) == done.end()) return;
    for (OverlayEdge& e : g.edges) e.known = false;
    done.assign(count, 0);
  }

  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t>& part_of = g.part;
  part_of.assign(count, kNone);
  // The connected parts, each with its lowest-leftmost vertex.
  std::vector<std::uint32_t>& seeds = g.seeds;
  std::vector<std::uint32_t>& stack = g.stack;
  seeds.clear();
  for (std::uint32_t v = 0; v < count; ++v) {
    if (part_of[v] != kNone) continue;
    const auto part = static_cast<std::uint32_t>(seeds.size());
    std::uint32_t seed = v;
    part_of[v] = part;
    stack.assign(1, v);
    while (!stack.empty()) {
      const std::uint32_t u = stack.back();
      stack.pop_back();
      const Point2& pu = g.index.point(u);
      const Point2& ps = g.index.point(seed);
      if (pu.x < ps.x || (pu.x == ps.x && pu.y < ps.y)) seed = u;
      for (const std::uint32_t e : g.edges_at(u)) {
        const std::uint32_t w = far_end(g.edges[e], u);
        if (part_of[w] == kNone) {
          part_of[w] = part;
          stack.push_back(w);
        }
      }
    }
    seeds.push_back(seed);
  }
  // Parts are located against each other.
  const std::vector<Winding> outside = seeds.size() > 1 ? windings_outside_parts(loops, g, seeds)
                                                        : std::vector<Winding>(seeds.size());
  for (std::uint32_t part = 0; part < seeds.size(); ++part) {
    spread_part(g, seeds[part], outside[part]);
  }
}

}  // namespace shadowgen::clipper::detail
