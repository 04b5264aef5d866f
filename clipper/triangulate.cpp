#include "clipper/triangulate.h"

#include <algorithm>
#include <limits>
#include <unordered_map>
#include <utility>

#include "clipper/normalize.h"
#include "clipper/predicates.h"
#include "clipper/segment_contact.h"

namespace shadowgen::clipper {

namespace {

using clipper::orient2d;
using clipper::Point2;

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

int orientation(const Point2& a, const Point2& b, const Point2& c) {
  return static_cast<int>(orient2d(a, b, c));
}

// A vertex as the triangulation sees it: its point and its number in the caller's loops.
struct Vertex {
  Point2 p;
  std::size_t index;
};
using Ring = std::vector<Vertex>;

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
// bridges and ear tests below then see it. Vertices are found by a sweep in x.
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

struct Node {
  Point2 p;
  std::size_t index;  // the vertex's number in the caller's loops
  std::size_t prev = kNone;
  std::size_t next = kNone;
};

class EarClipper {
 public:
  std::optional<std::vector<Triangle>> run(std::span<const clipper::Loop2> loops) {
    std::vector<Ring> rings;
    std::size_t first = 0;
    for (const clipper::Loop2& loop : loops) {
      Ring ring = clean(loop, first);
      first += loop.size();
      if (ring.size() >= 3 || rings.empty()) rings.push_back(std::move(ring));
    }
    if (rings[0].size() < 3) return std::vector<Triangle>{};
    // Work on a counter-clockwise outer loop with clockwise holes; the polygon's interior
    // then lies left of every edge, bridges included.
    const bool flipped = !counter_clockwise(rings[0]);
    if (flipped) std::reverse(rings[0].begin(), rings[0].end());
    for (std::size_t h = 1; h < rings.size(); ++h) {
      if (counter_clockwise(rings[h])) std::reverse(rings[h].begin(), rings[h].end());
    }
    if (rings.size() > 1) split_at_touching_points(rings);

    const std::size_t start = make_ring(rings[0]);
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
      if (!bridge(start, m)) return std::nullopt;
    }

    std::vector<Triangle> triangles = clip_ears(start);
    if (flipped) {
      for (Triangle& t : triangles) std::swap(t[0], t[2]);
    }
    return triangles;
  }

 private:
  std::size_t make_ring(const Ring& ring) {
    const std::size_t base = nodes_.size();
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      nodes_.push_back({ring[i].p, ring[i].index, base + (i + n - 1) % n, base + (i + 1) % n});
    }
    return base;
  }

  const Point2& at(std::size_t n) const { return nodes_[n].p; }
  const Point2& prev_at(std::size_t n) const { return nodes_[nodes_[n].prev].p; }
  const Point2& next_at(std::size_t n) const { return nodes_[nodes_[n].next].p; }

  // Direction n -> w points strictly into the polygon's interior at node n (the interior
  // lies left of the ring).
  bool locally_inside(std::size_t n, const Point2& w) const {
    const Point2& a = prev_at(n);
    const Point2& b = at(n);
    const Point2& c = next_at(n);
    const bool left_of_in = orientation(a, b, w) > 0;
    const bool left_of_out = orientation(b, c, w) > 0;
    if (orientation(a, b, c) > 0) return left_of_in && left_of_out;
    return left_of_in || left_of_out;
  }

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

  std::vector<Node> nodes_;
  std::vector<std::size_t> pending_;  // holes not yet bridged: a node of each
  std::vector<bool> removed_;         // cut from the ring
  // The boundary ring's nodes by point, for the holes that touch it.
  std::unordered_map<Point2, std::vector<std::size_t>, clipper::Point2Hash> ring_at_;
};

}  // namespace

std::optional<std::vector<Triangle>> triangulate(std::span<const clipper::Loop2> loops) {
  if (loops.empty()) return std::vector<Triangle>{};
  return EarClipper().run(loops);
}

}  // namespace shadowgen::clipper
