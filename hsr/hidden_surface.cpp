#include "hsr/hidden_surface.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <glm/geometric.hpp>
#include <optional>
#include <queue>
#include <stdexcept>
#include <utility>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/merge.h"
#include "detail/half_plane.h"
#include "hsr/convex_window.h"
#include "hsr/image_regions.h"
#include "hsr/parallel.h"
#include "hsr/spatial_grid.h"

namespace shadowgen::hsr {
namespace {

using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;

// Relative bound on the error of a nearness difference: evaluating two affine functions,
// whose coefficients are themselves rounded from the planes, costs a few dozen ulps of the
// magnitudes summed. Differences below it are ties.
constexpr double kTieTolerance = 0x1p-48;

// Tiles for wide polygons: blocks of this many grid cells a side.
constexpr int kTileBlock = 4;

struct Piece {
  PolygonWithHoles2 shape;
  std::size_t parent = 0;
};

// Runs a clip that works on input polygon `parent`; a clip that fails is passed on naming
// that polygon (PolygonClipError).
template <class Clip>
auto clip_of(std::size_t parent, Clip&& clip) {
  return clipper::failing_as<PolygonClipError>(parent, std::forward<Clip>(clip));
}

// The part of `piece` within rectangle `r` (a tile of a wide polygon, an image region).
// One clip, for the caller to count.
PolygonSet2 within_rectangle(const Piece& piece, const clipper::Box2& r) {
  const PolygonWithHoles2 rect{
      {{r.xmin, r.ymin}, {r.xmax, r.ymin}, {r.xmax, r.ymax}, {r.xmin, r.ymax}}, {}};
  return clip_of(piece.parent, [&] { return clipper::clip(piece.shape, rect).inside; });
}

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

// Fragments of one parent that share edges joined: tiles of a wide polygon, pieces cut at
// region sides, pieces of one polygon that the templates left side by side. Parents are
// merged in parallel, in order.
std::vector<Fragment> merge_by_parent(std::vector<Fragment> fragments) {
  std::stable_sort(fragments.begin(), fragments.end(),
                   [](const Fragment& a, const Fragment& b) { return a.parent < b.parent; });
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    if (i == 0 || fragments[i].parent != fragments[i - 1].parent) starts.push_back(i);
  }
  starts.push_back(fragments.size());
  std::vector<PolygonSet2> merged(starts.size() - 1);
  for_each_in_parallel(merged.size(), [&](std::size_t g) {
    PolygonSet2 group;
    for (std::size_t i = starts[g]; i < starts[g + 1]; ++i) {
      group.push_back(std::move(fragments[i].shape));
    }
    const std::size_t parent = fragments[starts[g]].parent;
    merged[g] = clip_of(parent, [&] { return clipper::merge_adjacent(group); });
  });
  std::vector<Fragment> out;
  for (std::size_t g = 0; g < merged.size(); ++g) {
    for (PolygonWithHoles2& p : merged[g])
      out.push_back({fragments[starts[g]].parent, std::move(p)});
  }
  return out;
}

// The pieces each region settles: whole where a piece's box lies in the region, else
// clipped to each region its box overlaps.
std::vector<std::vector<Piece>> split_into_regions(std::vector<Piece> pieces,
                                                   std::span<const clipper::Box2> regions,
                                                   HsrStats& stats) {
  std::vector<std::vector<Piece>> by_region(regions.size());
  if (regions.size() == 1) {
    by_region[0] = std::move(pieces);
    return by_region;
  }
  // Each piece's region, found in parallel; then the parts of the pieces that cross a
  // region's side, clipped to every region they reach, in parallel too; then the pieces
  // go to their regions in input order.
  constexpr std::size_t kAcross = static_cast<std::size_t>(-1);
  std::vector<std::size_t> home(pieces.size(), kAcross);
  for_each_in_parallel(pieces.size(), [&](std::size_t i) {
    const clipper::Box2 box = clipper::box_of(pieces[i].shape);
    const auto in = std::find_if(regions.begin(), regions.end(),
                                 [&box](const clipper::Box2& r) { return r.contains(box); });
    if (in != regions.end()) home[i] = static_cast<std::size_t>(in - regions.begin());
  });
  std::vector<std::size_t> across;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (home[i] == kAcross) across.push_back(i);
  }
  std::vector<std::vector<std::pair<std::size_t, PolygonWithHoles2>>> parts(across.size());
  std::vector<std::size_t> clips(across.size(), 0);
  for_each_in_parallel(across.size(), [&](std::size_t k) {
    const Piece& piece = pieces[across[k]];
    const clipper::Box2 box = clipper::box_of(piece.shape);
    for (std::size_t r = 0; r < regions.size(); ++r) {
      if (!regions[r].overlaps(box)) continue;
      ++clips[k];
      for (PolygonWithHoles2& q : within_rectangle(piece, regions[r])) {
        parts[k].emplace_back(r, std::move(q));
      }
    }
  });
  std::size_t k = 0;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (home[i] != kAcross) {
      by_region[home[i]].push_back(std::move(pieces[i]));
      continue;
    }
    stats.clips += clips[k];
    for (auto& [r, q] : parts[k++]) by_region[r].push_back({std::move(q), pieces[i].parent});
  }
  return by_region;
}

// Each region's area sort, in parallel; the fragments in region order. The failure passed
// on is the first region's, whatever the threads did.
std::vector<Fragment> sort_regions(std::vector<std::vector<Piece>> by_region,
                                   const std::vector<Nearness>& nearness,
                                   const std::vector<char>& facing, HsrStats& stats) {
  std::vector<std::vector<Fragment>> found(by_region.size());
  std::vector<HsrStats> region_stats(by_region.size());
  // The regions with the most pieces first, so that the last to finish is a small one
  // rather than one thread left with a large region while the others idle.
  std::vector<std::size_t> order(by_region.size());
  for (std::size_t r = 0; r < order.size(); ++r) order[r] = r;
  std::stable_sort(order.begin(), order.end(), [&by_region](std::size_t a, std::size_t b) {
    return by_region[a].size() > by_region[b].size();
  });
  std::vector<std::exception_ptr> failures(by_region.size());
  for_each_in_parallel(order.size(), [&](std::size_t k) {
    const std::size_t r = order[k];
    try {
      AreaSort(nearness, facing, region_stats[r]).run(std::move(by_region[r]), found[r]);
    } catch (...) {
      failures[r] = std::current_exception();
    }
  });
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
  std::vector<Fragment> fragments;
  for (std::size_t r = 0; r < found.size(); ++r) {
    stats.templates += region_stats[r].templates;
    stats.clips += region_stats[r].clips;
    stats.depth_errors += region_stats[r].depth_errors;
    stats.depth_splits += region_stats[r].depth_splits;
    stats.cycle_breaks += region_stats[r].cycle_breaks;
    for (Fragment& f : found[r]) fragments.push_back(std::move(f));
  }
  return fragments;
}

}  // namespace

VisibleSurfaces remove_hidden_surfaces(std::span<const Polygon3> polygons, const View& view,
                                       const HsrOptions& options) {
  std::vector<Plane3> planes(polygons.size());
  for_each_in_parallel(polygons.size(), [&](std::size_t i) { planes[i] = plane_of(polygons[i]); });
  return remove_hidden_surfaces(polygons, planes, view, options);
}

VisibleSurfaces remove_hidden_surfaces(std::span<const Polygon3> polygons,
                                       std::span<const Plane3> planes, const View& view,
                                       const HsrOptions& options) {
  if (planes.size() != polygons.size()) {
    throw std::invalid_argument("remove_hidden_surfaces: one plane per polygon");
  }
  VisibleSurfaces result;
  HsrStats& stats = result.stats;
  stats.input_polygons = polygons.size();
  result.planes.assign(planes.begin(), planes.end());
  result.nearness.resize(polygons.size());
  std::vector<char> facing(polygons.size(), 0);
  // Each polygon's nearness and image, in parallel; the pieces then in input order.
  std::vector<PolygonSet2> images(polygons.size());
  std::vector<char> edge_on(polygons.size(), 0);
  for_each_in_parallel(polygons.size(), [&](std::size_t i) {
    // Relative to the eye: far from the origin, the order of two faces meeting at an edge
    // (a wall on the ground) depends on offsets that the absolute plane loses.
    const glm::dvec3& normal = result.planes[i].normal;
    const std::optional<Nearness> nearness =
        view.nearness_on(normal, view.offset_from_eye(polygons[i].outer, normal));
    if (!nearness) {
      edge_on[i] = 1;
      return;
    }
    result.nearness[i] = *nearness;
    facing[i] = view.is_perspective() ? view.offset_from_eye(polygons[i].outer, normal) < 0.0
                                      : glm::dot(normal, view.forward()) < 0.0;
    images[i] = clip_of(i, [&] { return project_polygon(polygons[i], view, planes[i]); });
  });
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (edge_on[i]) {
      ++stats.edge_on;
    } else if (images[i].empty()) {
      ++stats.outside_view;
    } else {
      ++stats.projected_polygons;
      for (PolygonWithHoles2& p : images[i]) pieces.push_back({std::move(p), i});
    }
  }

  std::vector<clipper::Box2> boxes;
  boxes.reserve(pieces.size());
  for (const Piece& p : pieces) boxes.push_back(clipper::box_of(p.shape));
  const std::size_t count = options.regions ? options.regions : region_count_for(pieces.size());
  const std::vector<clipper::Box2> regions = image_regions(boxes, count);
  stats.regions = regions.size();
  result.fragments = sort_regions(split_into_regions(std::move(pieces), regions, stats),
                                  result.nearness, facing, stats);
  stats.fragments_before_merge = result.fragments.size();
  if (options.merge_fragments) result.fragments = merge_by_parent(std::move(result.fragments));
  // Pieces that meet exactly can get vertices an ulp apart from two chains of clips, each
  // rounded on its own; the needle left between them is thinner than the rounding of its
  // coordinates and is no visible piece (hidden_surface.h).
  const std::size_t before = result.fragments.size();
  std::erase_if(result.fragments, [](const Fragment& f) {
    return clipper::area(f.shape) <= clipper::rounding_area_bound(f.shape.outer);
  });
  stats.slivers_dropped = before - result.fragments.size();
  stats.fragments = result.fragments.size();
  return result;
}

}  // namespace shadowgen::hsr
