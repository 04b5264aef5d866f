#pragma once

// Polygon area-sort hidden-surface removal (Weiler and Atherton, "Hidden Surface Removal
// Using Polygon Area Sorting", SIGGRAPH 1977), the engine of Atherton, Weiler and
// Greenberg's shadow generator: run from a light it finds the lit areas, from the eye the
// visible ones. Exact in object space: the output is polygons, not samples.
//
// The algorithm as published:
//   1. a rough depth sort, nearest first;
//   2. the front polygon becomes the template; every polygon whose image overlaps it is
//      clipped by the Weiler–Atherton clipper into inside and outside pieces;
//   3. inside pieces lying behind the template are removed;
//   4. an inside piece in front of the template somewhere is a depth-sort error: it
//      becomes the template over its own area, recursively. A piece that crosses the
//      template's plane (interpenetration) is first split along the line where the two
//      planes meet; only its front part can be an error. The recursion works on ever
//      smaller areas and a template never recurs on its own stack, so cyclic overlap
//      (three sticks each over the next) terminates;
//   5. go on with the outside pieces.
//
// Depth ties (coplanar overlapping polygons, shared edges in 3D) go to the template:
// differences of nearness within the rounding bound of evaluating the two planes count
// as zero. That bound is relative, about 2^-48 of the magnitudes involved. Where two
// polygons tie over all of a piece and only one is seen from its front, that one shows,
// whichever is the template, so coplanar pairs such as the ground and a box's floor do
// not depend on the input order.
//
// Regions. The image is cut into rectangles settled independently, in parallel
// (image_regions.h), on oneTBB's threads: as many as the calling task arena allows.
//
// Cost. Templates find the polygons they overlap through a uniform grid over image-space
// bounding boxes (polygons wider than many cells are kept on a short list of their own),
// so for scenes of bounded depth complexity the work grows close to linearly with the
// number of polygons.

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "clipper/polygon.h"
#include "hsr/polygon3.h"
#include "hsr/view.h"

namespace shadowgen::hsr {

// A visible piece of input polygon `parent` (its index in the input), in image
// coordinates. Fragments never overlap each other, and none is thinner than the rounding
// of its own coordinates (area within clipper::rounding_area_bound): such needles, left
// where pieces that meet exactly got vertices an ulp apart from separately rounded clips,
// are dropped, which changes the visible area by less than that bound.
struct Fragment {
  std::size_t parent = 0;
  clipper::PolygonWithHoles2 shape;
};

struct HsrStats {
  std::size_t input_polygons = 0;
  std::size_t projected_polygons = 0;  // with area in the view, after frustum clipping
  std::size_t edge_on = 0;             // seen edge-on: no area in the image
  std::size_t outside_view = 0;        // wholly outside the frustum
  std::size_t regions = 0;             // of the image, settled independently (image_regions.h)
  std::size_t templates = 0;
  std::size_t clips = 0;
  std::size_t depth_errors = 0;  // recursions on a piece in front of its template
  std::size_t depth_splits = 0;  // interpenetrations split along the planes' line
  std::size_t cycle_breaks = 0;  // recursion refused because the template was on the stack
  std::size_t fragments_before_merge = 0;
  std::size_t slivers_dropped = 0;  // after the merge: thinner than their own rounding
  std::size_t fragments = 0;
};

struct HsrOptions {
  // Merge fragments of one parent that share whole edges (cheap: no new clipping).
  bool merge_fragments = true;
  // Regions of the image settled independently and in parallel (image_regions.h); 0: as
  // many as region_count_for the number of pieces. The result depends on the regions,
  // never on the threads.
  std::size_t regions = 0;
};

struct VisibleSurfaces {
  std::vector<Fragment> fragments;
  // Per input polygon: its 3D plane and, when it has area in the view, its nearness.
  std::vector<Plane3> planes;
  std::vector<Nearness> nearness;
  HsrStats stats;
};

// A clip failed (clipper::SnapRoundingError, clipper/clip.h) while working on input
// polygon `polygon`: the one whose piece was being clipped, or whose image or fragments
// were. remove_hidden_surfaces throws it in place of the clipper's error, so that the
// caller can name what the polygon stands for; no visible surfaces come back.
class PolygonClipError : public std::runtime_error {
 public:
  PolygonClipError(std::size_t polygon, const std::string& problem)
      : std::runtime_error("input polygon " + std::to_string(polygon) + ": " + problem),
        polygon_(polygon),
        problem_(problem) {}

  std::size_t polygon() const { return polygon_; }
  const std::string& problem() const { return problem_; }  // the clipper's message

 private:
  std::size_t polygon_;
  std::string problem_;
};

// Throws PolygonClipError where a clip fails.
VisibleSurfaces remove_hidden_surfaces(std::span<const Polygon3> polygons, const View& view,
                                       const HsrOptions& options = {});

// The same with each polygon's plane given (planes[i] == plane_of(polygons[i])), as
// shadow generation has them for every light: not worked out again.
VisibleSurfaces remove_hidden_surfaces(std::span<const Polygon3> polygons,
                                       std::span<const Plane3> planes, const View& view,
                                       const HsrOptions& options = {});

// The image of `polygon` in `view`: clipped to the view's frustum (near plane first, in
// 3D, so polygons crossing it are cut, never dropped), then projected. Empty when nothing
// of it is in view or it is seen edge-on. Throws clipper::SnapRoundingError where the cut
// to the frustum fails.
clipper::PolygonSet2 project_polygon(const Polygon3& polygon, const View& view);
// The same with the polygon's plane given (plane == plane_of(polygon)).
clipper::PolygonSet2 project_polygon(const Polygon3& polygon, const View& view,
                                     const Plane3& plane);

}  // namespace shadowgen::hsr
