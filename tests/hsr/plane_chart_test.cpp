// The plane chart: the one tie rule, exact lifts of the vertices that came in, the
// orientation kept where the chart mirrors the plane, and new points on the plane far from
// the origin.

#include "hsr/plane_chart.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <random>
#include <vector>

#include "clipper/box.h"
#include "clipper/clip.h"
#include "clipper/normalize.h"
#include "clipper/polygon.h"
#include "hsr/area.h"
#include "hsr/polygon3.h"

namespace shadowgen::hsr {
namespace {

using glm::dvec3;

constexpr ChartFrom kBoth[] = {ChartFrom::kWorld, ChartFrom::kOrigin};

// Newell's normal of the outer loop: which way round it runs, seen in 3D.
dvec3 turning(const Polygon3& p) { return newell_vector(p.outer); }

TEST(PlaneChart, DropsTheLargestComponent) {
  EXPECT_EQ(chart_facing({0.1, -0.2, 0.9}).dropped_axis, 2);
  EXPECT_EQ(chart_facing({0.1, -0.9, 0.2}).dropped_axis, 1);
  EXPECT_EQ(chart_facing({-0.9, 0.1, 0.2}).dropped_axis, 0);
  // Kept coordinates in cyclic order: (y, z), (z, x), (x, y).
  const dvec3 p(1.0, 2.0, 3.0);
  EXPECT_EQ(PlaneChart{0}(p), (clipper::Point2{2.0, 3.0}));
  EXPECT_EQ(PlaneChart{1}(p), (clipper::Point2{3.0, 1.0}));
  EXPECT_EQ(PlaneChart{2}(p), (clipper::Point2{1.0, 2.0}));
}

TEST(PlaneChart, TiesGoToZThenY) {
  const double h = std::sqrt(0.5);
  EXPECT_EQ(chart_facing({h, h, 0.0}).dropped_axis, 1);
  EXPECT_EQ(chart_facing({-h, h, 0.0}).dropped_axis, 1);
  EXPECT_EQ(chart_facing({h, 0.0, -h}).dropped_axis, 2);
  EXPECT_EQ(chart_facing({0.0, h, h}).dropped_axis, 2);
  EXPECT_EQ(chart_facing({1.0, -1.0, 1.0}).dropped_axis, 2);
  // A zero normal (a loop without area) gets the (x, y) chart.
  EXPECT_EQ(chart_facing({0.0, 0.0, 0.0}).dropped_axis, 2);
}

// A tilted triangle-fan polygon with a hole, coordinates that the plane's equation does
// not give back exactly, shifted by `offset`.
Polygon3 tilted_polygon(const dvec3& offset) {
  const dvec3 u(0.7, 0.1, 0.3), v(-0.2, 0.6, 0.45);
  auto at = [&](double s, double t) { return offset + s * u + t * v; };
  return {{at(0, 0), at(3, 0), at(3.5, 2), at(1, 3.25), at(-0.5, 1.5)},
          {{at(1, 1), at(1.2, 2), at(2, 1.5)}}};
}

TEST(ChartedPlane, LiftsKnownVerticesExactly) {
  for (const dvec3 offset : {dvec3(0.0), dvec3(1e8, -3e7, 2e8)}) {
    const Polygon3 polygon = tilted_polygon(offset);
    const Plane3 plane = plane_of(polygon);
    for (const ChartFrom from : kBoth) {
      ChartedPlane chart(plane.normal, polygon.outer[0], from);
      const clipper::PolygonWithHoles2 flat = chart.flatten_known(polygon);
      for (std::size_t i = 0; i < polygon.outer.size(); ++i) {
        EXPECT_EQ(chart.lift(flat.outer[i]), polygon.outer[i]);
      }
      for (std::size_t i = 0; i < polygon.holes[0].size(); ++i) {
        EXPECT_EQ(chart.lift(flat.holes[0][i]), polygon.holes[0][i]);
      }
      // Through the clipper: a clip that cuts nothing gives back the very vertices.
      const clipper::Box2 box = clipper::box_of(flat);
      const clipper::PolygonWithHoles2 around{{{box.xmin - 1, box.ymin - 1},
                                               {box.xmax + 1, box.ymin - 1},
                                               {box.xmax + 1, box.ymax + 1},
                                               {box.xmin - 1, box.ymax + 1}},
                                              {}};
      const std::vector<Polygon3> back = chart.lift(clipper::intersection({flat}, {around}));
      ASSERT_EQ(back.size(), 1u);
      for (const dvec3& p : back[0].outer) {
        EXPECT_NE(std::find(polygon.outer.begin(), polygon.outer.end(), p), polygon.outer.end());
      }
      ASSERT_EQ(back[0].holes.size(), 1u);
      for (const dvec3& p : back[0].holes[0]) {
        EXPECT_NE(std::find(polygon.holes[0].begin(), polygon.holes[0].end(), p),
                  polygon.holes[0].end());
      }
    }
  }
}

TEST(OwnChart, LiftsThePolygonsVerticesBackAndRefusesPolygonsWithoutArea) {
  const Polygon3 polygon = tilted_polygon(dvec3(1e8, -3e7, 2e8));
  const std::optional<OwnChart> own = own_chart(polygon);
  ASSERT_TRUE(own.has_value());
  EXPECT_EQ(own->chart.normal(), plane_of(polygon).normal);
  EXPECT_EQ(own->chart.lift(own->flat).outer, polygon.outer);
  EXPECT_EQ(own->chart.lift(own->flat).holes, polygon.holes);
  // On a line, a point, nothing: no chart.
  EXPECT_FALSE(own_chart(Polygon3{{dvec3(0, 0, 0), dvec3(1, 1, 1), dvec3(2, 2, 2)}, {}}));
  EXPECT_FALSE(own_chart(Polygon3{{dvec3(1, 2, 3), dvec3(1, 2, 3), dvec3(1, 2, 3)}, {}}));
  EXPECT_FALSE(own_chart(Polygon3{}));
}

TEST(ChartedPlane, WorldChartIsExact) {
  const Polygon3 polygon = tilted_polygon(dvec3(1e8, -3e7, 2e8));
  const ChartedPlane chart(plane_of(polygon).normal, polygon.outer[0], ChartFrom::kWorld);
  for (const dvec3& p : polygon.outer) EXPECT_EQ(chart.flatten(p), chart.chart()(p));
  // A point not known keeps its kept coordinates exactly.
  const clipper::Point2 q{1e8 + 0.375, -3e7 + 1.25};
  EXPECT_EQ(chart.flatten(chart.on_plane(q)), q);
}

// Outer loops come back counter-clockwise seen from the side the normal points to, holes
// the other way, whatever the sign of the dropped component.
TEST(ChartedPlane, KeepsTheFrontSide) {
  for (const double sign : {1.0, -1.0}) {
    for (const int axis : {0, 1, 2}) {
      dvec3 normal(0.2, -0.3, 0.1);
      normal[axis] = sign;
      normal = glm::normalize(normal);
      // A square and a hole in the plane, counter-clockwise seen from the normal's side.
      const dvec3 u = glm::normalize(glm::cross(normal, dvec3(0.3, 0.5, 0.7)));
      const dvec3 v = glm::cross(normal, u);
      const dvec3 o(5.0, -2.0, 7.0);
      const Polygon3 square{{o, o + 4.0 * u, o + 4.0 * u + 4.0 * v, o + 4.0 * v},
                            {{o + u + v, o + u + 2.0 * v, o + 2.0 * u + 2.0 * v}}};
      ASSERT_GT(glm::dot(turning(square), normal), 0.0);
      for (const ChartFrom from : kBoth) {
        ChartedPlane chart(normal, o, from);
        EXPECT_EQ(chart.chart().dropped_axis, axis);
        EXPECT_EQ(chart.mirrors(), sign < 0.0);
        const clipper::PolygonWithHoles2 flat = chart.flatten_known(square);
        EXPECT_EQ(clipper::signed_area(flat.outer) > 0.0, sign > 0.0);
        // The clipper's own orientation (outer loops counter-clockwise in the chart).
        const std::vector<Polygon3> back = chart.lift(clipper::normalized({flat}));
        ASSERT_EQ(back.size(), 1u);
        EXPECT_GT(glm::dot(turning(back[0]), normal), 0.0);
        ASSERT_EQ(back[0].holes.size(), 1u);
        EXPECT_LT(glm::dot(newell_vector(back[0].holes[0]), normal), 0.0);
        EXPECT_NEAR(area(back[0]), area(square), 1e-12);
      }
    }
  }
}

// Far from the origin, a new point is placed on the plane with the precision of the
// polygon's size: a point of the plane with representable coordinates comes back exactly.
TEST(ChartedPlane, NewPointsFarFromTheOrigin) {
  const dvec3 o(1e8, 1e8, 1e8);
  // The plane through o spanned by (4, 0, 1) and (0, 4, 2), its normal (−1, −2, 4)/√21.
  const Polygon3 triangle{{o, o + dvec3(4, 0, 1), o + dvec3(0, 4, 2)}, {}};
  const Plane3 plane = plane_of(triangle);
  ASSERT_EQ(chart_facing(plane.normal).dropped_axis, 2);
  for (const ChartFrom from : kBoth) {
    ChartedPlane chart(plane.normal, o, from);
    chart.flatten_known(triangle);
    for (const dvec3& d : {dvec3(1, 1, 0.75), dvec3(2, 0.5, 0.75), dvec3(-8, 12, 4)}) {
      const dvec3 p = o + d;  // on the plane, every coordinate exact
      EXPECT_EQ(chart.lift(chart.flatten(p)), p);
    }
  }
}

// A wall: the normal has no z component; the chart drops x or y, keeps z, and new points
// lie on the wall.
TEST(ChartedPlane, VerticalPlane) {
  for (const dvec3 normal : {dvec3(0.6, 0.8, 0.0), dvec3(-0.8, 0.6, 0.0), dvec3(0.0, -1.0, 0.0)}) {
    const dvec3 o(3.0, -1.0, 2.5);
    for (const ChartFrom from : kBoth) {
      const ChartedPlane chart(normal, o, from);
      EXPECT_NE(chart.chart().dropped_axis, 2);
      std::mt19937_64 rng(7);
      std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
      for (int k = 0; k < 100; ++k) {
        const clipper::Point2 q{coordinate(rng), coordinate(rng)};
        const dvec3 p = chart.on_plane(q);
        EXPECT_NEAR(glm::dot(normal, p - o), 0.0, 1e-14);
        const clipper::Point2 back = chart.flatten(p);
        EXPECT_NEAR(back.x, q.x, 1e-14);
        EXPECT_NEAR(back.y, q.y, 1e-14);
      }
    }
  }
}

// A negative dropped component mirrors the chart: clipping there and lifting back keeps
// the polygon's turning, and new points still land on the plane.
TEST(ChartedPlane, NegativeDroppedComponent) {
  const dvec3 o(-2.0, 4.0, 1e6);
  const Polygon3 floor_seen_from_below{
      {o, o + dvec3(0, 2, 0.25), o + dvec3(2, 2, 0.5), o + dvec3(2, 0, 0.25)}, {}};
  const Plane3 plane = plane_of(floor_seen_from_below);
  ASSERT_LT(plane.normal.z, 0.0);
  for (const ChartFrom from : kBoth) {
    ChartedPlane chart(plane.normal, o, from);
    ASSERT_TRUE(chart.mirrors());
    const clipper::PolygonWithHoles2 flat = chart.flatten_known(floor_seen_from_below);
    const clipper::Point2 c = chart.flatten(o + dvec3(1, 1, 0.25));
    // The half toward -x of x = o.x + 1: two new vertices, on the plane.
    const clipper::PolygonWithHoles2 half{
        {{c.x - 10, c.y - 10}, {c.x, c.y - 10}, {c.x, c.y + 10}, {c.x - 10, c.y + 10}}, {}};
    const std::vector<Polygon3> back = chart.lift(clipper::intersection({flat}, {half}));
    ASSERT_EQ(back.size(), 1u);
    EXPECT_GT(glm::dot(turning(back[0]), plane.normal), 0.0);
    EXPECT_NEAR(area(back[0]), 0.5 * area(floor_seen_from_below), 1e-9);
    for (const dvec3& p : back[0].outer) {
      EXPECT_NEAR(plane.signed_distance(p) - plane.signed_distance(o), 0.0, 1e-9);
    }
  }
}

TEST(ChartedPlane, DotOnPlaneIsAffineOnTheChart) {
  const Polygon3 polygon = tilted_polygon(dvec3(30.0, -20.0, 10.0));
  const Plane3 plane = plane_of(polygon);
  const dvec3 g(0.3, -0.5, 0.8);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  for (const ChartFrom from : kBoth) {
    const ChartedPlane chart(plane.normal, polygon.outer[2], from);
    const ChartAffine f = chart.dot_on_plane(g);
    for (int k = 0; k < 100; ++k) {
      const clipper::Point2 q{coordinate(rng), coordinate(rng)};
      EXPECT_NEAR(f.at(q), glm::dot(g, chart.on_plane(q)), 1e-12);
    }
  }
}

}  // namespace
}  // namespace shadowgen::hsr
