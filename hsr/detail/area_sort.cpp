#include "area_sort.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <queue>
#include <utility>

#include "half_plane.h"
#include "hsr/convex_window.h"
#include "hsr/spatial_grid.h"

namespace shadowgen::hsr::detail {
namespace {

using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

// Relative bound on the error of a nearness difference: evaluating two affine functions,
// whose coefficients are themselves rounded from the planes, costs a few dozen ulps of the
// magnitudes summed. Differences below it are ties.
constexpr double kTieTolerance = 0x1p-48;

// Tiles for wide polygons: blocks of this many grid cells a side.
constexpr int kTileBlock = 4;

enum class DepthOrder { kBehindOrTied, kInFront, kCrossing };

class AreaSort {
 public:
  AreaSort(const std::vector<Nearness>& nearness, const std::vector<char>& facing, HsrStats& stats)
      : nearness_(nearness), facing_(facing), stats_(stats) {}

  void run(std::vector<Piece> pieces, std::vector<Fragment>& out) {
    out_ = &out;
    clipper::Box2 extent;
    for (const Piece& p : pieces) extent.add(clipper::box_of(p.shape));
    SpatialGrid grid(extent, pieces.size());
    std::vector<clipper::Box2> boxes;
    std::vector<bool> alive;
    // Rough depth sort: nearest first, by each piece's nearest vertex; ties by parent so
    // the order does not depend on the input order more than the geometry does.
    using Entry = std::pair<double, std::size_t>;
    auto later = [&pieces](const Entry& a, const Entry& b) {
      if (a.first != b.first) return a.first < b.first;
      return pieces[a.second].parent > pieces[b.second].parent;
    };
    std::priority_queue<Entry, std::vector<Entry>, decltype(later)> queue(later);
    auto add = [&](Piece piece) {
      const std::size_t id = pieces.size();
      boxes.push_back(clipper::box_of(piece.shape));
      alive.push_back(true);
      grid.insert(id, boxes.back());
      const double key = nearest(piece);
      pieces.push_back(std::move(piece));
      queue.push({key, id});
    };
    std::vector<Piece> initial = std::move(pieces);
    pieces.clear();
    for (Piece& p : initial) {
      const clipper::Box2 box = clipper::box_of(p.shape);
      if (!grid.is_wide(box)) {
        add(std::move(p));
        continue;
      }
      // A polygon spanning much of the image (a ground plane) would be clipped by every
      // template over it, each time in whole: cut it into tiles first, so each template
      // clips only the tiles it covers. Tiles of one parent merge again at the end.
      for (const clipper::Box2& t : grid.tiles(box, kTileBlock)) {
        ++stats_.clips;
        for (PolygonWithHoles2& q : within_rectangle(p, t)) {
          add({std::move(q), p.parent});
        }
      }
    }

    std::vector<std::size_t> candidates;
    while (!queue.empty()) {
      const std::size_t t = queue.top().second;
      queue.pop();
      if (!alive[t]) continue;
      alive[t] = false;
      grid.erase(t);
      ++stats_.templates;
      const Piece template_piece = pieces[t];
      const ConvexWindow template_window(template_piece.shape);
      const clipper::Box2 tbox = boxes[t];
      candidates.clear();
      grid.query(tbox, candidates);
      std::vector<Piece> inside;
      for (std::size_t c : candidates) {
        if (!alive[c] || !boxes[c].overlaps(tbox)) continue;
        ++stats_.clips;
        // Most candidates lie beside the template: they stay as they are.
        std::optional<clipper::ClipResult> near = clip_of(
            pieces[c].parent, [&] { return template_window.clip_unless_apart(pieces[c].shape); });
        if (!near || near->inside.empty()) continue;
        clipper::ClipResult& r = *near;
        alive[c] = false;
        grid.erase(c);
        const std::size_t parent = pieces[c].parent;
        for (PolygonWithHoles2& p : r.inside) inside.push_back({std::move(p), parent});
        for (PolygonWithHoles2& p : r.outside) add({std::move(p), parent});
      }
      std::vector<std::size_t> stack{template_piece.parent};
      resolve({template_piece.shape}, template_piece.parent, std::move(inside), stack);
    }
  }

 private:
  double nearest(const Piece& p) const {
    const Nearness& n = nearness_[p.parent];
    double best = -INFINITY;
    for (const clipper::Point2& v : p.shape.outer) best = std::max(best, n.at(v));
    return best;
  }

  // Where `piece` lies relative to the plane of `front_parent`, over the piece: affine
  // differences take their extremes at the outer loop's vertices.
  DepthOrder order(const Piece& piece, std::size_t front_parent) const {
    const Nearness& np = nearness_[piece.parent];
    const Nearness& nt = nearness_[front_parent];
    bool ahead = false, behind = false;
    for (const clipper::Point2& v : piece.shape.outer) {
      const double d = np.at(v) - nt.at(v);
      const double scale = std::fabs(np.a * v.x) + std::fabs(np.b * v.y) + std::fabs(np.c) +
                           std::fabs(nt.a * v.x) + std::fabs(nt.b * v.y) + std::fabs(nt.c);
      const double tol = kTieTolerance * scale;
      if (d > tol) ahead = true;
      if (d < -tol) behind = true;
    }
    if (!ahead && !behind && facing_[piece.parent] && !facing_[front_parent]) {
      // Tied everywhere (coplanar): the side seen from its front shows, whichever of the
      // two is the template (the ground under a box's floor, seen into the box through
      // the near plane), so the answer does not depend on the input order.
      return DepthOrder::kInFront;
    }
    if (!ahead) return DepthOrder::kBehindOrTied;
    return behind ? DepthOrder::kCrossing : DepthOrder::kInFront;
  }

  // The part of `piece` in front of the plane of `front_parent`: split along the line
  // where the two planes' nearness is equal.
  void front_part(const Piece& piece, std::size_t front_parent, std::vector<Piece>& out) {
    ++stats_.depth_splits;
    const Nearness& np = nearness_[piece.parent];
    const Nearness& nt = nearness_[front_parent];
    const PolygonWithHoles2 half = detail::half_plane_in_box(np.a - nt.a, np.b - nt.b, np.c - nt.c,
                                                             clipper::box_of(piece.shape));
    if (half.outer.empty()) return;
    ++stats_.clips;
    for (PolygonWithHoles2& p :
         clip_of(piece.parent, [&] { return clipper::clip(piece.shape, half).inside; })) {
      out.push_back({std::move(p), piece.parent});
    }
  }

  // Settles the visibility of `region` (all of it covered by `parent`) against the
  // pieces of other polygons lying within it.
  void resolve(PolygonSet2 region, std::size_t parent, std::vector<Piece> within,
               std::vector<std::size_t>& stack) {
    std::vector<Piece> offenders;
    for (Piece& p : within) {
      switch (order(p, parent)) {
        case DepthOrder::kBehindOrTied:
          break;  // hidden by the template
        case DepthOrder::kInFront:
          offenders.push_back(std::move(p));
          break;
        case DepthOrder::kCrossing:
          front_part(p, parent, offenders);
          break;
      }
    }
    // A piece whose polygon is already a template further up cannot truly be in front
    // here; only rounding says so. Refusing it is what makes cycles terminate.
    std::erase_if(offenders, [&](const Piece& p) {
      const bool on_stack = std::find(stack.begin(), stack.end(), p.parent) != stack.end();
      if (on_stack) ++stats_.cycle_breaks;
      return on_stack;
    });
    if (offenders.empty()) {
      for (PolygonWithHoles2& p : region) out_->push_back({parent, std::move(p)});
      return;
    }
    // Depth-sort error: the nearest offender becomes the template over its own area.
    ++stats_.depth_errors;
    std::size_t best = 0;
    double best_key = -INFINITY;
    for (std::size_t i = 0; i < offenders.size(); ++i) {
      const double key = nearest(offenders[i]);
      if (key > best_key) {
        best_key = key;
        best = i;
      }
    }
    Piece front = std::move(offenders[best]);
    offenders.erase(offenders.begin() + static_cast<std::ptrdiff_t>(best));
    std::vector<Piece> in_front_area, elsewhere;
    const ConvexWindow front_window(front.shape);
    for (Piece& p : offenders) {
      ++stats_.clips;
      clipper::ClipResult r = clip_of(p.parent, [&] { return front_window.clip(p.shape); });
      for (PolygonWithHoles2& q : r.inside) in_front_area.push_back({std::move(q), p.parent});
      for (PolygonWithHoles2& q : r.outside) elsewhere.push_back({std::move(q), p.parent});
    }
    ++stats_.clips;
    PolygonSet2 rest = clip_of(parent, [&] { return clipper::difference(region, {front.shape}); });
    stack.push_back(front.parent);
    const std::size_t front_parent = front.parent;
    resolve({std::move(front.shape)}, front_parent, std::move(in_front_area), stack);
    stack.pop_back();
    if (!rest.empty()) resolve(std::move(rest), parent, std::move(elsewhere), stack);
  }

  const std::vector<Nearness>& nearness_;
  const std::vector<char>& facing_;  // per polygon: seen from its front
  HsrStats& stats_;
  std::vector<Fragment>* out_ = nullptr;
};

}  // namespace

// The part of `piece` within rectangle `r` (a tile of a wide polygon, an image region).
// One clip, for the caller to count.
PolygonSet2 within_rectangle(const Piece& piece, const clipper::Box2& r) {
  const PolygonWithHoles2 rect{
      {{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}}, {}};
  return clip_of(piece.parent, [&] { return clipper::clip(piece.shape, rect).inside; });
}

void area_sort(std::vector<Piece> pieces, const std::vector<Nearness>& nearness,
               const std::vector<char>& facing, HsrStats& stats, std::vector<Fragment>& out) {
  AreaSort(nearness, facing, stats).run(std::move(pieces), out);
}

}  // namespace shadowgen::hsr::detail
