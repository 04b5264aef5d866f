#include "loop_pieces.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include "clipper/predicates.h"

namespace shadowgen::scene::detail {

namespace {

using clipper::orient2d;
using clipper::Orientation;
using clipper::Point2;

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::size_t> parent_;
};

// The steps of check_pieces, over one loop: link the edges past the bridges, check the
// directions alternate around every point, then orient the pieces against each other.
class PieceChecker {
 public:
  PieceChecker(const CleanLoop& loop, std::span<const std::uint32_t> bridge_partner,
               const std::string& name, LoopPieces& pieces)
      : loop_(loop),
        p_(loop.points),
        n_(static_cast<std::uint32_t>(loop.points.size())),
        bridge_partner_(bridge_partner),
        name_(name),
        pieces_(pieces) {}

  PiecesCheck run() {
    PiecesCheck result;
    result.problem = link_edges();
    if (!result.problem) result.problem = check_alternation();
    if (!result.problem) result.problem = check_piece_windings(result.counter_clockwise);
    return result;
  }

 private:
  bool is_bridge(std::uint32_t edge) const {
    return !bridge_partner_.empty() && bridge_partner_[edge] != kNoEdge;
  }

  // After each edge that is no bridge, the next such edge the loop takes.
  std::optional<std::string> link_edges() {
    pieces_.next_edge.assign(n_, kNoEdge);
    for (std::uint32_t k = 0; k < n_; ++k) {
      if (is_bridge(k)) continue;
      std::uint32_t j = (k + 1) % n_;
      for (std::uint32_t steps = 0; is_bridge(j); ++steps) {
        if (steps > n_) return name_ + " has no area in the face's plane";
        j = (bridge_partner_[j] + 1) % n_;
      }
      pieces_.next_edge[k] = j;
      pieces_.edges_in[p_[(k + 1) % n_]].push_back(k);
    }
    if (pieces_.edges_in.empty()) {
      return name_ + " has no area in the face's plane: it runs along every edge both ways";
    }
    return std::nullopt;
  }

  std::vector<Ray> rays_at(const std::vector<std::uint32_t>& in) const {
    std::vector<Ray> rays;
    for (const std::uint32_t k : in) {
      rays.push_back({p_[k], false});
      rays.push_back({p_[(pieces_.next_edge[k] + 1) % n_], true});
    }
    return rays;
  }

  // The directions in and out of each point, counter-clockwise: they must alternate, or
  // the winding number would step twice the same way around the point.
  std::optional<std::string> check_alternation() const {
    for (const auto& [point, in] : pieces_.edges_in) {
      if (in.size() < 2) continue;
      const Point2& at = point;  // a structured binding, which older clangs cannot capture
      std::vector<Ray> rays = rays_at(in);
      std::sort(rays.begin(), rays.end(),
                [&at](const Ray& a, const Ray& b) { return angle_less(at, a.to, b.to); });
      for (std::size_t i = 0; i < rays.size(); ++i) {
        if (rays[i].out == rays[(i + 1) % rays.size()].out) {
          return name_ + " overlaps itself at vertex " + vertex_name(loop_, (in[0] + 1) % n_) +
                 ": around it, it covers an area twice or runs the wrong way round";
        }
      }
    }
    return std::nullopt;
  }

  // The pieces: the bridge-free edges joined at shared points.
  void join_pieces() {
    for (const auto& [at, in] : pieces_.edges_in) node_.emplace(at, node_.size());
    sets_ = DisjointSets(node_.size());
    for (std::uint32_t k = 0; k < n_; ++k) {
      if (!is_bridge(k)) sets_.join(node_.at(p_[k]), node_.at(p_[(k + 1) % n_]));
    }
  }

  // Alone, a piece winds 0 around the points outside it and, since its directions
  // alternate, the same +1 or -1 beside all its edges on their other side: +1 when, at
  // its lowest point (x, then y), where all its directions point into one half-plane, the
  // first of them counter-clockwise from straight down is an edge out of the point.
  // Nodes in map order meet each piece first at its lowest point. By piece: that point
  // and the inner winding.
  std::map<std::size_t, std::pair<Point2, int>> lowest_points() {
    std::map<std::size_t, std::pair<Point2, int>> lowest;
    for (const auto& [at, in] : pieces_.edges_in) {
      const std::size_t piece = sets_.find(node_.at(at));
      if (lowest.count(piece) != 0) continue;
      const std::vector<Ray> rays = rays_at(in);
      const Ray* first = &rays[0];
      for (const Ray& r : rays) {
        if (orient2d(at, r.to, first->to) == Orientation::kCounterClockwise) first = &r;
      }
      lowest.emplace(piece, std::pair<Point2, int>(at, first->out ? 1 : -1));
    }
    return lowest;
  }

  // Together the pieces wind 0 or +-1 everywhere when, beside the edges of every piece,
  // the winding number takes the two values it takes beside the piece through the loop's
  // lowest point, which no other piece surrounds: the others must wind 0 around a piece
  // that runs the loop's way round, and the loop's +-1 around one that runs the other
  // way (an inner boundary of the region).
  std::optional<std::string> check_piece_windings(bool& counter_clockwise) {
    join_pieces();
    const std::map<std::size_t, std::pair<Point2, int>> lowest = lowest_points();
    const std::size_t first_piece = sets_.find(node_.begin()->second);
    const int base = lowest.at(first_piece).second > 0 ? 0 : -1;
    for (const auto& [piece, low] : lowest) {
      if (piece == first_piece) continue;
      int around = low.second > 0 ? 0 : -1;
      for (std::uint32_t k = 0; k < n_; ++k) {
        if (is_bridge(k) || sets_.find(node_.at(p_[k])) == piece) continue;
        around += winding(p_[k], p_[(k + 1) % n_], low.first);
      }
      if (around != base) {
        const std::uint32_t k = pieces_.edges_in.at(low.first)[0];
        return name_ + " overlaps itself: the part of it through vertex " +
               vertex_name(loop_, (k + 1) % n_) +
               " lies in its own region and runs the same way round, or outside it and the "
               "other way";
      }
    }
    counter_clockwise = base == 0;
    return std::nullopt;
  }

  const CleanLoop& loop_;
  const std::vector<Point2>& p_;
  std::uint32_t n_;
  std::span<const std::uint32_t> bridge_partner_;
  const std::string& name_;
  LoopPieces& pieces_;
  std::map<Point2, std::size_t> node_;  // each point with an edge into it, numbered
  DisjointSets sets_{0};                // of node_, by the pieces' edges
};

}  // namespace

PiecesCheck check_pieces(const CleanLoop& loop, std::span<const std::uint32_t> bridge_partner,
                         const std::string& name, LoopPieces& pieces) {
  return PieceChecker(loop, bridge_partner, name, pieces).run();
}

}  // namespace shadowgen::scene::detail
