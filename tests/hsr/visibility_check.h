#pragma once

// The whole check of one hidden-surface removal against its two oracles.
//
// Coverage (CGAL, exact): the fragments are valid polygons, they do not overlap (the sum
// of their areas equals the area of their union) and together they cover exactly the
// union of the inputs' images (hsr::project_polygon): the sum of the fragments' areas
// equals the union's area and (∪ fragments) Δ (∪ images) has no area, both relative to
// the union's area.
//
// Visibility (RayOracle, brute force in 3D): at random image points over the images'
// bounding box, the one fragment covering the point belongs to a polygon the oracle sees
// nearest along that ray (within the depth tie), no fragment covers a point where the
// ray sees nothing, and no point is covered twice. Skipped, and counted: points outside
// a perspective view's window, points within `edge_band` of an edge of an image or of a
// fragment (there the answer changes, and rounding decides on which side a point lies),
// and points where the oracle itself cannot decide (a polygon's boundary or the near
// plane at the nearest depth).
//
// Lost polygons: every polygon with an image of positive area has fragments, or is
// really hidden: at random points inside it (in 3D, so slivers seen almost edge-on are
// probed too) the oracle never sees it alone in front.
//
// Tolerances scale with the scene: L is the diagonal of the scene's bounding box and U
// the spacing of doubles at its largest coordinate (what rounding the input itself costs
// far from the origin). Depth tie 1e-11·L + 64U; boundary margin 1e-9·L + 64U; edge band
// 1e-9 of the sampled image box plus 64U (orthographic) or 64U/near (perspective, where
// a world length d at depth z is d/z in the image).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "hsr/hidden_surface.h"
#include "tests/hsr/scenes.h"

namespace shadowgen::test {

struct VisibilityCheckOptions {
  std::size_t samples = 100000;
  std::uint64_t seed = 1;
  double relative_area_tolerance = 1e-9;
  std::size_t lost_probes = 200;  // interior points tried per polygon without fragments
  hsr::HsrOptions hsr;            // how the removal runs (regions of the image...)
};

struct VisibilityCheck {
  // Tolerances used (see above).
  double extent = 0.0;
  double depth_tie = 0.0;
  double margin = 0.0;
  double edge_band = 0.0;

  // Coverage: exact areas.
  std::size_t invalid_images = 0;
  std::size_t invalid_fragments = 0;
  double image_union = 0.0;
  double fragment_sum = 0.0;
  double fragment_union = 0.0;
  double symmetric_difference = 0.0;

  // Visibility at sample points.
  std::size_t samples = 0;
  std::size_t outside_window = 0;
  std::size_t near_edge = 0;
  std::size_t ambiguous = 0;
  std::size_t checked = 0;
  std::size_t wrong_polygon = 0;  // covered by a fragment of a polygon not seen nearest
  std::size_t uncovered = 0;      // the ray sees a polygon, no fragment covers the point
  std::size_t spurious = 0;       // a fragment covers a point where the ray sees nothing
  std::size_t overlapping = 0;    // two fragments cover the point
  // Over checked points: depth of the covering fragment's polygon minus the nearest
  // depth, relative to L (within the depth tie when all is well).
  double worst_depth_gap = 0.0;

  // Lost polygons.
  std::size_t with_image = 0;
  std::size_t without_fragments = 0;
  std::size_t lost = 0;

  std::vector<std::string> failures;            // the first few, in words
  std::vector<clipper::Point2> failure_points;  // image points of failing samples

  double area_error() const;                  // |Σ fragments − ∪ images| / ∪ images
  double symmetric_difference_error() const;  // |(∪ fragments) Δ (∪ images)| / ∪ images
  double overlap_error() const;               // (Σ fragments − ∪ fragments) / ∪ images
  bool passed(double relative_area_tolerance) const;
  std::string summary() const;
};

VisibilityCheck check_visibility(std::span<const hsr::Polygon3> polygons, const hsr::View& view,
                                 const hsr::VisibleSurfaces& result,
                                 const VisibilityCheckOptions& options = {});

// One line of hsr::HsrStats.
std::string describe(const hsr::HsrStats& stats);

// Runs hidden-surface removal on every view of `scene`, checks each result, prints one
// line per view (errors, sample counts, stats, time) and reports failures, with a
// picture <scene>-view<k>.svg of images, fragments and failing points in the build
// folder's test-artifacts.
void ExpectVisibilityMatchesOracles(const Scene& scene, const VisibilityCheckOptions& options = {});

// Visible area of each input polygon: the exact area of its fragments.
std::vector<double> visible_area_by_parent(const hsr::VisibleSurfaces& result,
                                           std::size_t polygon_count);

// For every view of `scene`: the visible area of each polygon is the same, within
// relative_tolerance × the area of the polygon's image, for the input as given and for
// `shuffles` random permutations of it. Prints the worst relative difference per view.
void ExpectOrderIndependent(const Scene& scene, int shuffles, std::uint64_t seed,
                            double relative_tolerance = 1e-9);

}  // namespace shadowgen::test
