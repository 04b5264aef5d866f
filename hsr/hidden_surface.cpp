#include "hsr/hidden_surface.h"

#include <algorithm>
#include <exception>
#include <glm/geometric.hpp>
#include <optional>
#include <stdexcept>
#include <utility>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/merge.h"
#include "detail/area_sort.h"
#include "hsr/concatenated.h"
#include "hsr/image_regions.h"
#include "hsr/index_groups.h"
#include "hsr/parallel.h"

namespace shadowgen::hsr {
namespace {

using clipper::PolygonSet2;
using clipper::PolygonWithHoles2;
using detail::clip_of;
using detail::Piece;
using detail::within_rectangle;

// Fragments of one parent that share edges joined: tiles of a wide polygon, pieces cut at
// region sides, pieces of one polygon that the templates left side by side. Parents (each
// below `parents`) are grouped by a counting sort, merged in parallel, and come out in
// order, each parent's fragments in the order they came.
std::vector<Fragment> merge_by_parent(std::vector<Fragment> fragments, std::size_t parents) {
  const IndexGroups by_parent = index_groups(
      fragments.size(), parents, [&fragments](std::size_t i) { return fragments[i].parent; });
  std::vector<std::vector<Fragment>> merged(parents);
  for_each_in_parallel(parents, [&](std::size_t parent) {
    if (by_parent.first(parent) == by_parent.last(parent)) return;
    PolygonSet2 group;
    for (std::size_t j = by_parent.first(parent); j < by_parent.last(parent); ++j) {
      group.push_back(std::move(fragments[by_parent.order[j]].shape));
    }
    for (PolygonWithHoles2& p : clip_of(parent, [&] { return clipper::merge_adjacent(group); })) {
      merged[parent].push_back({parent, std::move(p)});
    }
  });
  return concatenated(std::move(merged));
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
  // The regions with the most pieces first, each thread taking the next one not yet
  // taken when it is free (largest first, the classic list schedule), so that the last to
  // finish is a small one rather than one thread left with a large region while the
  // others idle. Each region writes only its own slots: the result does not depend on
  // which thread sorted it.
  std::vector<std::size_t> order(by_region.size());
  for (std::size_t r = 0; r < order.size(); ++r) order[r] = r;
  std::stable_sort(order.begin(), order.end(), [&by_region](std::size_t a, std::size_t b) {
    return by_region[a].size() > by_region[b].size();
  });
  std::vector<std::exception_ptr> failures(by_region.size());
  for_each_taken_in_order(order.size(), [&](std::size_t k) {
    const std::size_t r = order[k];
    try {
      detail::area_sort(std::move(by_region[r]), nearness, facing, region_stats[r], found[r]);
    } catch (...) {
      failures[r] = std::current_exception();
    }
  });
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
  for (const HsrStats& region : region_stats) {
    stats.templates += region.templates;
    stats.clips += region.clips;
    stats.depth_errors += region.depth_errors;
    stats.depth_splits += region.depth_splits;
    stats.cycle_breaks += region.cycle_breaks;
  }
  return concatenated(std::move(found));
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
  std::vector<std::vector<Piece>> images(polygons.size());
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
    for (PolygonWithHoles2& p :
         clip_of(i, [&] { return project_polygon(polygons[i], view, planes[i]); })) {
      images[i].push_back({std::move(p), i});
    }
  });
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (edge_on[i]) {
      ++stats.edge_on;
    } else if (images[i].empty()) {
      ++stats.outside_view;
    } else {
      ++stats.projected_polygons;
    }
  }
  std::vector<Piece> pieces = concatenated(std::move(images));

  std::vector<clipper::Box2> boxes(pieces.size());
  for_each_in_parallel(pieces.size(),
                       [&](std::size_t i) { boxes[i] = clipper::box_of(pieces[i].shape); });
  const std::size_t count = options.regions ? options.regions : region_count_for(pieces.size());
  const std::vector<clipper::Box2> regions = image_regions(boxes, count);
  stats.regions = regions.size();
  result.fragments = sort_regions(split_into_regions(std::move(pieces), regions, stats),
                                  result.nearness, facing, stats);
  stats.fragments_before_merge = result.fragments.size();
  if (options.merge_fragments) {
    result.fragments = merge_by_parent(std::move(result.fragments), polygons.size());
  }
  // Pieces that meet exactly can get vertices an ulp apart from two chains of clips, each
  // rounded on its own; the needle left between them is thinner than the rounding of its
  // coordinates and is no visible piece (hidden_surface.h). Which ones, in parallel.
  const std::size_t before = result.fragments.size();
  std::vector<char> sliver(before, 0);
  for_each_in_parallel(before, [&](std::size_t i) {
    const PolygonWithHoles2& shape = result.fragments[i].shape;
    sliver[i] = clipper::area(shape) <= clipper::rounding_area_bound(shape.outer);
  });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < before; ++i) {
    if (sliver[i]) continue;
    if (kept != i) result.fragments[kept] = std::move(result.fragments[i]);
    ++kept;
  }
  result.fragments.resize(kept);
  stats.slivers_dropped = before - result.fragments.size();
  stats.fragments = result.fragments.size();
  return result;
}

}  // namespace shadowgen::hsr
