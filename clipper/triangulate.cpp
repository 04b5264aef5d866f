#include "clipper/triangulate.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "detail/hole_bridge.h"
#include "detail/node_ring.h"

namespace shadowgen::clipper {

namespace {

using detail::orientation;

// Ears cut from the one ring that hole_bridge.h makes of the polygon.
class EarClipper : public detail::NodeRings {
 public:
  explicit EarClipper(detail::NodeRings rings) : NodeRings(std::move(rings)) {}

  // Cuts ears until a triangle is left. When a whole turn finds no ear (only through
  // degeneracies), it cuts a vertex between collinear neighbours (no area in the plane),
  // then any convex vertex, then any vertex, so it always ends.
  std::vector<Triangle> clip_ears(std::size_t start) {
    std::vector<std::size_t> ring;
    std::size_t n = start;
    do {
      ring.push_back(n);
      n = nodes_[n].next;
    } while (n != start);
    std::size_t count = ring.size();
    removed_.assign(nodes_.size(), false);
    std::size_t ear = start;
    drop_degenerate(ring, count, ear);

    std::vector<Triangle> triangles;
    triangles.reserve(count);
    std::size_t stop = ear;
    int stage = 0;
    while (count > 3) {
      const std::size_t a = nodes_[ear].prev;
      const std::size_t c = nodes_[ear].next;
      bool cut = false;
      switch (stage) {
        case 0:
          cut = is_ear(ear);
          break;
        case 1:
          cut = orientation(at(a), at(ear), at(c)) == 0;
          break;
        case 2:
          cut = orientation(at(a), at(ear), at(c)) > 0;
          break;
        default:
          cut = true;
      }
      if (cut) {
        triangles.push_back({nodes_[a].index, nodes_[ear].index, nodes_[c].index});
        unlink(ear);
        --count;
        ear = c;
        drop_degenerate({a, c}, count, ear);
        stop = ear;
        stage = 0;
        continue;
      }
      ear = c;
      if (ear == stop) ++stage;
    }
    if (count == 3 && orientation(prev_at(ear), at(ear), next_at(ear)) >= 0) {
      triangles.push_back(
          {nodes_[nodes_[ear].prev].index, nodes_[ear].index, nodes_[nodes_[ear].next].index});
    }
    return triangles;
  }

 private:
  // The ear test of Mapbox's earcut: no vertex lies in the closed triangle a, b, c; if
  // one did, the diagonal a-c would not lie in the polygon. A vertex at one of the
  // corners (a copy that a bridge made, or a point where loops touch) blocks only when one
  // of its edges leaves it into the triangle.
  bool is_ear(std::size_t b) const {
    const std::size_t a = nodes_[b].prev;
    const std::size_t c = nodes_[b].next;
    const Point2& pa = at(a);
    const Point2& pb = at(b);
    const Point2& pc = at(c);
    if (orientation(pa, pb, pc) <= 0) return false;
    const double xmin = std::min({pa.x, pb.x, pc.x});
    const double xmax = std::max({pa.x, pb.x, pc.x});
    const double ymin = std::min({pa.y, pb.y, pc.y});
    const double ymax = std::max({pa.y, pb.y, pc.y});
    // Strictly inside the triangle's angle at a corner. An edge along a side is no
    // obstacle: along the diagonal it is where the rest of the polygon pinches.
    auto enters = [&](const Point2& corner, const Point2& w) {
      const bool ab = orientation(pa, pb, w) > 0;
      const bool bc = orientation(pb, pc, w) > 0;
      const bool ca = orientation(pc, pa, w) > 0;
      if (corner == pa) return ab && ca;
      if (corner == pb) return ab && bc;
      return bc && ca;
    };
    for (std::size_t n = nodes_[c].next; n != a; n = nodes_[n].next) {
      const Point2& p = at(n);
      if (p.x < xmin || p.x > xmax || p.y < ymin || p.y > ymax) continue;
      if (p == pa || p == pb || p == pc) {
        if (enters(p, prev_at(n)) || enters(p, next_at(n))) return false;
        continue;
      }
      if (orientation(pa, pb, p) >= 0 && orientation(pb, pc, p) >= 0 &&
          orientation(pc, pa, p) >= 0) {
        return false;
      }
    }
    return true;
  }

  void unlink(std::size_t n) {
    nodes_[nodes_[n].prev].next = nodes_[n].next;
    nodes_[nodes_[n].next].prev = nodes_[n].prev;
    removed_[n] = true;
  }

  // A node that bounds no area: at the same point as a neighbour, or the tip of a needle
  // (its neighbours on one line, on the same side of it). Cutting ears next to pinch
  // points (bridges, touching loops) leaves such needles behind; removing them changes no
  // region, and leaving them would let a later "ear" span one.
  bool degenerate(std::size_t n) const {
    const Point2& a = prev_at(n);
    const Point2& p = at(n);
    const Point2& c = next_at(n);
    if (p == a || p == c) return true;
    if (orientation(a, p, c) != 0) return false;
    return !((a < p && p < c) || (c < p && p < a));
  }

  // Removes degenerate nodes among `work` and, as removals make new neighbours, around
  // them. Keeps `ear` on a node still in the ring.
  void drop_degenerate(std::vector<std::size_t> work, std::size_t& count, std::size_t& ear) {
    while (!work.empty() && count > 2) {
      const std::size_t n = work.back();
      work.pop_back();
      if (removed_[n] || !degenerate(n)) continue;
      const std::size_t a = nodes_[n].prev;
      const std::size_t c = nodes_[n].next;
      unlink(n);
      --count;
      if (ear == n) ear = c;
      work.push_back(a);
      work.push_back(c);
    }
  }

  std::vector<bool> removed_;  // cut from the ring
};

}  // namespace

std::optional<std::vector<Triangle>> triangulate(std::span<const clipper::Loop2> loops) {
  if (loops.empty()) return std::vector<Triangle>{};
  std::optional<detail::BridgedPolygon> polygon = detail::bridge_holes(loops);
  if (!polygon) return std::nullopt;
  if (polygon->start == detail::kNoNode) return std::vector<Triangle>{};
  std::vector<Triangle> triangles = EarClipper(std::move(polygon->rings)).clip_ears(polygon->start);
  if (polygon->flipped) {
    for (Triangle& t : triangles) std::swap(t[0], t[2]);
  }
  return triangles;
}

}  // namespace shadowgen::clipper
