#include "detail/hole_bridge.h"

#include <algorithm>
#include <unordered_map>
#include <utility>
#include <vector>

#include "clipper/normalize.h"
#include "clipper/segment_contact.h"

namespace shadowgen::clipper::detail {

namespace {

// One loop with consecutive repeats dropped.
Ring clean(const clipper::Loop2& loop, std::size_t first) {
  Ring out;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (!out.empty() && out.back().p == loop[i]) continue;
    out.push_back({loop[i], first + i});
  }
  while (out.size() > 1 && out.back().p == out.front().p) out.pop_back();
  return out;
}

bool counter_clockwise(const Ring& ring) {
  clipper::Loop2 points;
  points.reserve(ring.size());
  for (const Vertex& v : ring) points.push_back(v.p);
  return clipper::is_counter_clockwise(points);
}

// Where a loop touches another inside one of its edges, the touching vertex is added to
// that edge too, so that every touching point is a vertex of each loop through it: the
// bridges here and the ear tests after them see it. Vertices are found by a sweep in x.
void split_at_touching_points(std::vector<Ring>& rings) {
  struct Located {
    Point2 p;
    std::size_t index;
    std::size_t ring;
  };
  std::vector<Located> vertices;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (const Vertex& v : rings[r]) vertices.push_back({v.p, v.index, r});
  }
  std::sort(vertices.begin(), vertices.end(),
            [](const Located& a, const Located& b) { return a.p < b.p; });
  for (std::size_t r = 0; r < rings.size(); ++r) {
    Ring split;
    const Ring& ring = rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vertex& a = ring[i];
      const Vertex& b = ring[(i + 1) % ring.size()];
      split.push_back(a);
      const Point2 lo = std::min(a.p, b.p);
      const Point2 hi = std::max(a.p, b.p);
      auto first = std::upper_bound(vertices.begin(), vertices.end(), lo,
                                    [](const Point2& p, const Located& v) { return p < v.p; });
      std::vector<Vertex> inside;
      for (auto it = first; it != vertices.end() && it->p < hi; ++it) {
        if (it->ring == r) continue;
        if (it->p.y < std::min(a.p.y, b.p.y) || it->p.y > std::max(a.p.y, b.p.y)) continue;
        if (orientation(a.p, b.p, it->p) != 0) continue;
        if (!inside.empty() && inside.back().p == it->p) continue;
        inside.push_back({it->p, it->index});
      }
      if (b.p < a.p) std::reverse(inside.begin(), inside.end());
      split.insert(split.end(), inside.begin(), inside.end());
    }
    rings[r] = std::move(split);
  }
}

// The holes joined one by one into the ring of the outer loop.
class HoleBridger : public NodeRings {
 public:
  // `rings`: the outer loop counter-clockwise, then the holes clockwise.
  bool run(const std::vector<Ring>& rings, std::size_t& start) {
    start = make_ring(rings[0]);
    std::vector<std::size_t> holes;  // the rightmost node of each hole
    for (std::size_t h = 1; h < rings.size(); ++h) {
      const std::size_t ring = make_ring(rings[h]);
      std::size_t rightmost = ring;
      for (std::size_t n = nodes_[ring].next; n != ring; n = nodes_[n].next) {
        if (at(rightmost) < at(n)) rightmost = n;
      }
      holes.push_back(rightmost);
    }
    // Rightmost holes first (Eberly): a hole's bridge then never needs to pass a hole
    // still to come.
    std::sort(holes.begin(), holes.end(),
              [&](std::size_t a, std::size_t b) { return at(b) < at(a); });
    pending_ = holes;
    index_ring(start);
    for (std::size_t m : holes) {
      pending_.erase(std::find(pending_.begin(), pending_.end(), m));
      if (!bridge(start, m)) return false;
    }
    return true;
  }

 private:
  // The edge [p, q] meets the segment [m, v] other than at m or v.
  static bool blocks(const Point2& m, const Point2& v, const Point2& p, const Point2& q) {
    const SegmentContact c = segment_contact(m, v, p, q);
    if (c.contact == Contact::kNone) return false;
    if (c.contact == Contact::kTouch) return c.at != m && c.at != v;
    return true;
  }

  // Whether the bridge m -> v lies inside the polygon: it meets no edge except at its
  // ends, and near each end it runs into the polygon's interior. Where several loops pass
  // through an end, the interior there is the union of the boundary ring's angles (the
  // ring may pass a point twice) within every unbridged hole's outside.
  bool valid_bridge(std::size_t start, std::size_t m, std::size_t v) const {
    const Point2& pm = at(m);
    const Point2& pv = at(v);
    if (!locally_inside(v, pm) || !locally_inside(m, pv)) return false;
    bool ring_at_m = false;
    bool ring_at_m_open = false;
    auto scan = [&](std::size_t ring, bool boundary) {
      std::size_t n = ring;
      do {
        if (blocks(pm, pv, at(n), next_at(n))) return false;
        if (n != v && n != m) {
          if (at(n) == pv && !boundary && !locally_inside(n, pm)) return false;
          if (at(n) == pm) {
            if (boundary) {
              ring_at_m = true;
              ring_at_m_open = ring_at_m_open || locally_inside(n, pv);
            } else if (!locally_inside(n, pv)) {
              return false;
            }
          }
        }
        n = nodes_[n].next;
      } while (n != ring);
      return true;
    };
    if (!scan(start, true) || !scan(m, false)) return false;
    for (std::size_t h : pending_) {
      if (!scan(h, false)) return false;
    }
    return !ring_at_m || ring_at_m_open;
  }

  void index_ring(std::size_t ring) {
    std::size_t n = ring;
    do {
      ring_at_[at(n)].push_back(n);
      n = nodes_[n].next;
    } while (n != ring);
  }

  // Joins the hole through m to the boundary ring through `start` (which ring_at_ indexes).
  //
  // Where the hole touches the ring, at a ring vertex v whose angle holds the hole's angle
  // at the same point h, the hole is spliced in there: v -> (the hole from h's successor
  // round to h) -> v's successor; any other bridge would make the ring go round the hole
  // twice. Otherwise by a bridge from m to a visible ring vertex v, walked both ways:
  // v -> m -> the hole -> m' -> v'. Candidates to the right of m are tried first, nearest
  // first: among them lies the vertex Eberly's ray cast would find.
  bool bridge(std::size_t start, std::size_t m) {
    std::size_t h = m;
    do {
      if (const auto it = ring_at_.find(at(h)); it != ring_at_.end()) {
        for (const std::size_t v : it->second) {
          if (!locally_inside(v, next_at(h)) || !locally_inside(v, prev_at(h))) continue;
          const std::size_t v_next = nodes_[v].next;
          const std::size_t h_next = nodes_[h].next;
          nodes_[v].next = h_next;
          nodes_[h_next].prev = v;
          nodes_[h].next = v_next;
          nodes_[v_next].prev = h;
          index_ring(h);
          return true;
        }
      }
      h = nodes_[h].next;
    } while (h != m);

    std::vector<std::size_t> candidates;
    std::size_t n = start;
    do {
      candidates.push_back(n);
      n = nodes_[n].next;
    } while (n != start);
    const Point2 pm = at(m);
    auto key = [&](std::size_t c) {
      const double dx = at(c).x - pm.x;
      const double dy = at(c).y - pm.y;
      return std::pair<bool, double>(at(c).x < pm.x, dx * dx + dy * dy);
    };
    std::sort(candidates.begin(), candidates.end(),
              [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
    for (std::size_t v : candidates) {
      if (at(v) == pm || !valid_bridge(start, m, v)) continue;
      const std::size_t m2 = nodes_.size();
      const std::size_t v2 = m2 + 1;
      const std::size_t v_next = nodes_[v].next;
      const std::size_t m_prev = nodes_[m].prev;
      nodes_.push_back({nodes_[m].p, nodes_[m].index, m_prev, v2});
      nodes_.push_back({nodes_[v].p, nodes_[v].index, m2, v_next});
      nodes_[v].next = m;
      nodes_[m].prev = v;
      nodes_[m_prev].next = m2;
      nodes_[v_next].prev = v2;
      index_ring(m);  // the hole's nodes and the two copies
      return true;
    }
    return false;
  }

  std::vector<std::size_t> pending_;  // holes not yet bridged: a node of each
  // The boundary ring's nodes by point, for the holes that touch it.
  std::unordered_map<Point2, std::vector<std::size_t>, Point2Hash> ring_at_;
};

}  // namespace

std::optional<BridgedPolygon> bridge_holes(std::span<const Loop2> loops) {
  std::vector<Ring> rings;
  std::size_t first = 0;
  for (const Loop2& loop : loops) {
    Ring ring = clean(loop, first);
    first += loop.size();
    if (ring.size() >= 3 || rings.empty()) rings.push_back(std::move(ring));
  }
  BridgedPolygon result;
  if (rings[0].size() < 3) return result;
  // A counter-clockwise outer loop with clockwise holes: the polygon's interior then lies
  // left of every edge, bridges included.
  result.flipped = !counter_clockwise(rings[0]);
  if (result.flipped) std::reverse(rings[0].begin(), rings[0].end());
  for (std::size_t h = 1; h < rings.size(); ++h) {
    if (counter_clockwise(rings[h])) std::reverse(rings[h].begin(), rings[h].end());
  }
  if (rings.size() > 1) split_at_touching_points(rings);
  HoleBridger bridger;
  if (!bridger.run(rings, result.start)) return std::nullopt;
  result.rings = std::move(bridger);
  return result;
}

}  // namespace shadowgen::clipper::detail
