// Hidden-surface removal on small hand-made scenes whose answers are known exactly.

#include "hsr/hidden_surface.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <iostream>
#include <random>
#include <span>
#include <vector>

#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "tests/hsr/scenes.h"
#include "tests/hsr/visibility_check.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen::test {
namespace {

using glm::dvec3;
using hsr::Polygon3;
using hsr::View;

// The square [x0, x1] × [y0, y1] at height z, counter-clockwise seen from above.
Polygon3 square(double x0, double y0, double x1, double y1, double z) {
  return {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, {}};
}

const View kFromAbove = View::orthographic({0.0, 0.0, -1.0}, {0.0, 0.0, 0.0});
const View kFromBelow = View::orthographic({0.0, 0.0, 1.0}, {0.0, 0.0, 0.0});

// The image of a world polygon (its vertices projected one by one): what a fragment
// should be, for polygons in front of the eye.
clipper::PolygonWithHoles2 image_of(const Polygon3& polygon, const View& view) {
  clipper::PolygonWithHoles2 image;
  for (const dvec3& p : polygon.outer) image.outer.push_back(view.project(p));
  for (const hsr::Loop3& hole : polygon.holes) {
    image.holes.emplace_back();
    for (const dvec3& p : hole) image.holes.back().push_back(view.project(p));
  }
  return image;
}

clipper::PolygonSet2 fragments_of(const hsr::VisibleSurfaces& result, std::size_t parent) {
  clipper::PolygonSet2 shapes;
  for (const hsr::Fragment& f : result.fragments) {
    if (f.parent == parent) shapes.push_back(f.shape);
  }
  return shapes;
}

// The region covered by `parent`'s fragments is exactly `expected` (in image coordinates).
void ExpectFragmentsAre(const hsr::VisibleSurfaces& result, std::size_t parent,
                        const clipper::PolygonSet2& expected) {
  const clipper::PolygonSet2 ours = fragments_of(result, parent);
  for (const clipper::PolygonWithHoles2& piece : ours) EXPECT_EQ(validity_problem(piece), "");
  const ExactUnionComparison c = compare_exact_unions(std::span(&ours, 1), std::span(&expected, 1));
  EXPECT_EQ(c.symmetric_difference, 0.0) << "polygon " << parent;
}

TEST(HiddenSurface, EmptyInputGivesNothing) {
  const hsr::VisibleSurfaces result = hsr::remove_hidden_surfaces({}, kFromAbove);
  EXPECT_TRUE(result.fragments.empty());
  EXPECT_EQ(result.stats.input_polygons, 0u);
  EXPECT_EQ(result.stats.templates, 0u);
}

TEST(HiddenSurface, NearerSquareHidesPartOfTheFartherOneExactly) {
  const Polygon3 high = square(0, 0, 2, 2, 1), low = square(1, 1, 3, 3, 0);
  // Both input orders, from above (high in front) and from below (low in front).
  for (const bool swap : {false, true}) {
    std::vector<Polygon3> input{high, low};
    if (swap) std::swap(input[0], input[1]);
    const std::size_t h = swap ? 1 : 0, l = swap ? 0 : 1;

    const hsr::VisibleSurfaces above = hsr::remove_hidden_surfaces(input, kFromAbove);
    std::vector<double> area = visible_area_by_parent(above, 2);
    EXPECT_EQ(area[h], 4.0);
    EXPECT_EQ(area[l], 3.0);
    ExpectFragmentsAre(above, h, {image_of(high, kFromAbove)});
    const Polygon3 l_shape{{{2, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}, {1, 2, 0}, {2, 2, 0}}, {}};
    ExpectFragmentsAre(above, l, {image_of(l_shape, kFromAbove)});

    const hsr::VisibleSurfaces below = hsr::remove_hidden_surfaces(input, kFromBelow);
    area = visible_area_by_parent(below, 2);
    EXPECT_EQ(area[h], 3.0);
    EXPECT_EQ(area[l], 4.0);
  }
}

TEST(HiddenSurface, FartherSquareShowsThroughAHole) {
  Polygon3 frame = square(0, 0, 4, 4, 1);
  frame.holes.push_back({{1, 1, 1}, {1, 3, 1}, {3, 3, 1}, {3, 1, 1}});
  const Polygon3 behind = square(0.5, 0.5, 3.5, 3.5, 0);
  const std::vector<Polygon3> input{frame, behind};
  const hsr::VisibleSurfaces result = hsr::remove_hidden_surfaces(input, kFromAbove);
  const std::vector<double> area = visible_area_by_parent(result, 2);
  EXPECT_EQ(area[0], 12.0);
  EXPECT_EQ(area[1], 4.0);
  ExpectFragmentsAre(result, 1, {image_of(square(1, 1, 3, 3, 0), kFromAbove)});
}

TEST(HiddenSurface, InterpenetratingQuadsSplitAlongTheLineWhereTheyMeet) {
  // A lies in z = x, B in z = -x: from above A is in front where x > 0, B where x < 0.
  const Polygon3 a{{{-1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, -1}}, {}};
  const Polygon3 b{{{-1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, 1}}, {}};
  for (const bool swap : {false, true}) {
    const std::vector<Polygon3> input = swap ? std::vector{b, a} : std::vector{a, b};
    const std::size_t ia = swap ? 1 : 0, ib = swap ? 0 : 1;
    const hsr::VisibleSurfaces result = hsr::remove_hidden_surfaces(input, kFromAbove);
    EXPECT_GE(result.stats.depth_splits, 1u);
    const std::vector<double> area = visible_area_by_parent(result, 2);
    EXPECT_NEAR(area[ia], 2.0, 1e-14);
    EXPECT_NEAR(area[ib], 2.0, 1e-14);
    // Every vertex of A's fragments lies on the side x >= 0 of the line x = 0 (within
    // the rounding of the constructed points), every vertex of B's on x <= 0.
    for (const hsr::Fragment& f : result.fragments) {
      for (const clipper::Point2& q : f.shape.outer) {
        const std::optional<dvec3> p = kFromAbove.unproject(q, result.planes[f.parent]);
        ASSERT_TRUE(p);
        if (f.parent == ia) {
          EXPECT_GE(p->x, -1e-15);
        } else {
          EXPECT_LE(p->x, 1e-15);
        }
      }
    }
  }
}

TEST(HiddenSurface, CoplanarOverlapGoesToOnePolygonWithoutOverlap) {
  const std::vector<Polygon3> input{square(0, 0, 2, 2, 0), square(1, 1, 3, 3, 0)};
  const hsr::VisibleSurfaces result = hsr::remove_hidden_surfaces(input, kFromAbove);
  const std::vector<double> area = visible_area_by_parent(result, 2);
  EXPECT_EQ(area[0] + area[1], 7.0);
  // Fragments may share edges, never area: their union is as large as their sum.
  clipper::PolygonSet2 all;
  for (const hsr::Fragment& f : result.fragments) {
    EXPECT_EQ(validity_problem(f.shape), "");
    all.push_back(f.shape);
  }
  EXPECT_EQ(exact_union_area(std::span(&all, 1)), 7.0);
}

TEST(HiddenSurface, PerspectiveNearPlaneCutsTheFloorExactly) {
  // Eye at the origin looking along +z, near plane z = 1; a floor at y = -1 from z = 0.5
  // to z = 2. What is seen is its part z in [1, 2]: image points (-x/z, -1/z), the
  // trapezoid between y = -1 (width 2) and y = -1/2 (width 1), area 3/4.
  const View view = View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 120.0, 1.0);
  const Polygon3 floor{{{-1, -1, 0.5}, {-1, -1, 2}, {1, -1, 2}, {1, -1, 0.5}}, {}};
  EXPECT_NEAR(clipper::area(hsr::project_polygon(floor, view)), 0.75, 1e-15);
  const Polygon3 before_near{{{-1, -1, 0.2}, {-1, -1, 0.8}, {1, -1, 0.8}, {1, -1, 0.2}}, {}};
  const Polygon3 behind_eye = square(-1, -1, 1, 1, -3);
  const std::vector<Polygon3> input{floor, before_near, behind_eye};
  const hsr::VisibleSurfaces result = hsr::remove_hidden_surfaces(input, view);
  EXPECT_EQ(result.stats.projected_polygons, 1u);
  EXPECT_EQ(result.stats.outside_view, 2u);
  const std::vector<double> area = visible_area_by_parent(result, 3);
  EXPECT_NEAR(area[0], 0.75, 1e-15);
  EXPECT_EQ(area[1], 0.0);
  EXPECT_EQ(area[2], 0.0);
  const Polygon3 seen{{{-1, -1, 1}, {-1, -1, 2}, {1, -1, 2}, {1, -1, 1}}, {}};
  const clipper::PolygonSet2 ours = fragments_of(result, 0);
  const clipper::PolygonSet2 expected{image_of(seen, view)};
  const ExactUnionComparison c = compare_exact_unions(std::span(&ours, 1), std::span(&expected, 1));
  EXPECT_LE(c.symmetric_difference, 1e-15);
}

// Through a perspective view's window (a point light's six views have one each), the
// image is the vertices' image clipped to the window, whether a polygon lies wholly
// inside it, wholly outside it (both settled without a clip) or across its sides; and
// the same, byte for byte, with the polygon's plane given.
TEST(HiddenSurface, ImagesThroughAWindowAreTheImagesClippedToIt) {
  const View view = View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 60.0, 0.1);
  const clipper::PolygonWithHoles2 window = *view.window();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> centre(-3.0, 3.0), offset(-0.4, 0.4), depth(2.0, 5.0);
  int inside = 0, outside = 0, crossing = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const dvec3 middle{centre(rng), centre(rng), depth(rng)};
    Polygon3 triangle;
    for (int k = 0; k < 3; ++k)
      triangle.outer.push_back(middle + dvec3{offset(rng), offset(rng), offset(rng)});
    const clipper::PolygonSet2 got = hsr::project_polygon(triangle, view);
    const clipper::PolygonSet2 whole = clipper::normalized({image_of(triangle, view)});
    const clipper::PolygonSet2 expected = clipper::intersection(whole, {window});
    const ExactUnionComparison c =
        compare_exact_unions(std::span(&got, 1), std::span(&expected, 1));
    EXPECT_LE(c.symmetric_difference, 1e-15 * c.b_union) << trial;
    const double seen = clipper::area(expected), all = clipper::area(whole);
    if (seen == 0.0) {
      ++outside;
      EXPECT_TRUE(got.empty()) << trial;
    } else if (seen == all) {
      ++inside;
    } else {
      ++crossing;
    }
    const clipper::PolygonSet2 given =
        hsr::project_polygon(triangle, view, hsr::plane_of(triangle));
    ASSERT_EQ(given.size(), got.size()) << trial;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(given[i].outer, got[i].outer) << trial;
      EXPECT_EQ(given[i].holes, got[i].holes) << trial;
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
  EXPECT_GT(crossing, 100);
}

TEST(HiddenSurface, EdgeOnPolygonIsCountedAndLeavesNoFragment) {
  // Orthographic from above: a wall in the plane x = 0.5 is seen edge-on.
  const Polygon3 wall{{{0.5, -1, 0}, {0.5, 1, 0}, {0.5, 1, 1}, {0.5, -1, 1}}, {}};
  const std::vector<Polygon3> input{wall, square(-1, -1, 1, 1, 0)};
  const hsr::VisibleSurfaces result = hsr::remove_hidden_surfaces(input, kFromAbove);
  EXPECT_EQ(result.stats.edge_on, 1u);
  EXPECT_EQ(result.stats.projected_polygons, 1u);
  const std::vector<double> area = visible_area_by_parent(result, 2);
  EXPECT_EQ(area[0], 0.0);
  EXPECT_EQ(area[1], 4.0);
  EXPECT_TRUE(hsr::project_polygon(wall, kFromAbove).empty());

  // Perspective: a polygon whose plane passes through the eye.
  const View view = View::perspective({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 90.0, 0.5);
  const Polygon3 through_eye{{{-1, 0, 2}, {1, 0, 2}, {1, 0, 3}, {-1, 0, 3}}, {}};
  const std::vector<Polygon3> seen_edge_on{through_eye};
  const hsr::VisibleSurfaces r = hsr::remove_hidden_surfaces(seen_edge_on, view);
  EXPECT_EQ(r.stats.edge_on, 1u);
  EXPECT_TRUE(r.fragments.empty());
}

TEST(HiddenSurface, CyclicSticksEachHideTheNext) {
  // A over B over C over A: no order of whole polygons is right, yet every stick is
  // partly hidden and the fragments cover the union of the images exactly.
  const Scene scene = cyclic_sticks(1, 1);
  const View view = make_view(scene.views[0]);
  const hsr::VisibleSurfaces result = hsr::remove_hidden_surfaces(scene.polygons, view);
  const std::vector<double> area = visible_area_by_parent(result, 3);
  std::vector<clipper::PolygonSet2> images;
  for (std::size_t i = 0; i < 3; ++i) {
    images.push_back(hsr::project_polygon(scene.polygons[i], view));
    EXPECT_LT(area[i], exact_area_of_pieces(images[i]) * (1.0 - 1e-3)) << "stick " << i;
    EXPECT_GT(area[i], 0.0);
  }
  const double union_area = exact_union_area(images);
  EXPECT_NEAR(area[0] + area[1] + area[2], union_area, 1e-12 * union_area);
  EXPECT_GE(result.stats.depth_errors, 1u);
  std::cout << describe(result.stats) << '\n';
}

TEST(HiddenSurface, MergingFragmentsKeepsEachPolygonsArea) {
  const Scene scene = triangle_soup(3, 40);
  const View view = make_view(scene.views[0]);
  const hsr::VisibleSurfaces merged = hsr::remove_hidden_surfaces(scene.polygons, view);
  const hsr::VisibleSurfaces unmerged =
      hsr::remove_hidden_surfaces(scene.polygons, view, {.merge_fragments = false});
  EXPECT_EQ(unmerged.stats.fragments, unmerged.stats.fragments_before_merge);
  EXPECT_LE(merged.fragments.size(), unmerged.fragments.size());
  const std::vector<double> a = visible_area_by_parent(merged, scene.polygons.size());
  const std::vector<double> b = visible_area_by_parent(unmerged, scene.polygons.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-14) << "polygon " << i;
}

// Regions of the image (hsr/image_regions.h) are settled on as many threads as the task
// arena has: the fragments are the same, byte for byte, on 1, 2 or 3 of them.
TEST(HiddenSurface, RegionsGiveTheSameFragmentsOnAnyThreadCount) {
  const Scene scene = triangle_soup(5, 150);
  const View view = make_view(scene.views[0]);
  auto on_threads = [&](int threads) {
    tbb::task_arena arena(threads);
    return arena.execute(
        [&] { return hsr::remove_hidden_surfaces(scene.polygons, view, {.regions = 9}); });
  };
  const hsr::VisibleSurfaces one = on_threads(1);
  EXPECT_EQ(one.stats.regions, 9u);
  for (int threads : {2, 3}) {
    const hsr::VisibleSurfaces more = on_threads(threads);
    ASSERT_EQ(more.fragments.size(), one.fragments.size()) << threads << " threads";
    for (std::size_t k = 0; k < one.fragments.size(); ++k) {
      EXPECT_EQ(more.fragments[k].parent, one.fragments[k].parent) << k;
      EXPECT_EQ(more.fragments[k].shape.outer, one.fragments[k].shape.outer) << k;
      EXPECT_EQ(more.fragments[k].shape.holes, one.fragments[k].shape.holes) << k;
    }
  }
}

// Cut into regions and merged again, every polygon keeps its visible area (to rounding:
// the cuts along region sides are rounded crossings).
TEST(HiddenSurface, RegionsKeepEachPolygonsVisibleArea) {
  const Scene scene = boxes_on_ground(9, 40);
  for (const ViewSpec& spec : scene.views) {
    const View view = make_view(spec);
    const hsr::VisibleSurfaces whole = hsr::remove_hidden_surfaces(scene.polygons, view);
    EXPECT_EQ(whole.stats.regions, 1u);
    for (std::size_t regions : {2u, 5u, 16u}) {
      const hsr::VisibleSurfaces cut =
          hsr::remove_hidden_surfaces(scene.polygons, view, {.regions = regions});
      EXPECT_GE(cut.stats.regions, regions / 2) << regions;
      const std::vector<double> a = visible_area_by_parent(whole, scene.polygons.size());
      const std::vector<double> b = visible_area_by_parent(cut, scene.polygons.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_NEAR(a[i], b[i], 1e-12) << "polygon " << i << ", " << regions << " regions";
      }
    }
  }
}

}  // namespace
}  // namespace shadowgen::test
