// The test support is code too: the oracle's validity verdicts against hand-made cases
// and against CGAL's is_valid_polygon_with_holes, its areas, the WKT reader and the
// generators.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "tests/support/cgal_oracle.h"
#include "tests/support/random_polygons.h"
#include "tests/support/transform.h"
#include "tests/support/wkb.h"
#include "tests/support/wkt.h"

namespace shadowgen::test {
namespace {

using clipper::Loop2;
using clipper::Point2;

Loop2 square(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Loop2 reversed(Loop2 loop) {
  std::reverse(loop.begin(), loop.end());
  return loop;
}

// Valid per validity_problem, and CGAL agrees.
void ExpectAccepted(const PolygonWithHoles2& polygon) {
  EXPECT_EQ(validity_problem(polygon), "");
  EXPECT_TRUE(cgal_accepts(polygon));
}

// Rejected with a message containing `reason`, and CGAL agrees.
void ExpectRejected(const PolygonWithHoles2& polygon, const std::string& reason) {
  const std::string problem = validity_problem(polygon);
  EXPECT_NE(problem.find(reason), std::string::npos) << "problem: \"" << problem << '"';
  EXPECT_FALSE(cgal_accepts(polygon));
}

TEST(OracleValidity, AcceptsPolygonsWithHolesAndVertexContacts) {
  ExpectAccepted({square(0, 0, 4, 4), {}});
  ExpectAccepted({square(0, 0, 4, 4), {reversed(square(1, 1, 2, 2))}});
  // A hole touching the outer loop at a common vertex (the outer has a vertex there).
  ExpectAccepted({{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{2, 0}, {1, 1}, {3, 1}}}});
  // Two holes meeting at a vertex.
  ExpectAccepted({square(0, 0, 6, 6), {{{1, 1}, {1, 3}, {3, 3}}, {{{3, 3}, {3, 5}, {5, 5}}}}});
  // Collinear vertices are valid (only the clipper's outputs promise to have none).
  ExpectAccepted({{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, {}});
}

TEST(OracleValidity, RejectsWhatCgalRejects) {
  ExpectRejected({reversed(square(0, 0, 4, 4)), {}}, "clockwise");
  ExpectRejected({square(0, 0, 4, 4), {square(1, 1, 2, 2)}}, "counter-clockwise");
  ExpectRejected({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}, "crosses itself");
  ExpectRejected({{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}}, {}}, "touches itself");
  ExpectRejected({{{0, 0}, {1, 0}, {1, 0}, {1, 1}}, {}}, "zero-length edge");
  ExpectRejected({{{0, 0}, {2, 0}, {1, 0}, {1, 1}}, {}}, "doubles back");
  ExpectRejected({{{0, 0}, {1, 0}}, {}}, "vertices");
  ExpectRejected({{{0, 0}, {1, 0}, {NAN, 1}}, {}}, "non-finite");
  // A hole vertex inside an edge of the outer loop: CGAL's "weak intersection".
  ExpectRejected({square(0, 0, 4, 4), {{{2, 0}, {1, 1}, {3, 1}}}}, "inside an edge");
  ExpectRejected({square(0, 0, 4, 4), {reversed(square(0, 1, 1, 2))}}, "overlap");
  ExpectRejected({square(0, 0, 4, 4), {reversed(square(3, 1, 5, 2))}}, "cross");
  ExpectRejected({square(0, 0, 4, 4), {reversed(square(5, 1, 6, 2))}}, "not inside");
  ExpectRejected({square(0, 0, 8, 8), {reversed(square(1, 1, 6, 6)), reversed(square(2, 2, 3, 3))}},
                 "lies inside");
  // A hole that leaves the outer loop and comes back through two common vertices, its
  // edges meeting the outer loop nowhere else.
  ExpectRejected({{{0, 0}, {2, 0}, {4, 0}, {4, 2}, {4, 4}, {0, 4}},
                  {reversed({{2, 0}, {5, -1}, {4, 2}, {2, 2}})}},
                 "common vertex");
}

TEST(OracleValidity, ContactsInsideEdgesAreFineForClipInputs) {
  // OGC and clip() allow a hole to touch the outer loop inside one of its edges; CGAL
  // does not (Contacts::kCommonVertices, the default).
  const PolygonWithHoles2 touching{square(0, 0, 4, 4), {{{2, 0}, {1, 1}, {3, 1}}}};
  EXPECT_NE(validity_problem(touching), "");
  EXPECT_EQ(validity_problem(touching, Contacts::kAnyPoint), "");
  EXPECT_EQ(input_problem({{reversed(touching.outer), {reversed(touching.holes[0])}}}), "");
  // Repeated consecutive vertices are fine for clip() (removed on entry).
  EXPECT_EQ(input_problem({{{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 0}}, {}}}), "");
  // Crossing is never fine.
  EXPECT_NE(input_problem({{square(0, 0, 4, 4), {reversed(square(3, 1, 5, 2))}}}), "");
  EXPECT_NE(
      validity_problem({square(0, 0, 4, 4), {{{1, 1}, {3, 1}, {2, -1}}}}, Contacts::kAnyPoint), "");
}

TEST(OracleValidity, StricterThanCgalOnLoopsThatTouchThemselves) {
  // CGAL accepts a "relatively simple" outer loop pinched at a vertex; the clipper
  // promises simple loops, so the oracle rejects it.
  const PolygonWithHoles2 pinched{{{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}}, {}};
  EXPECT_NE(validity_problem(pinched), "");
}

TEST(OracleValidity, Sets) {
  const PolygonWithHoles2 a{square(0, 0, 2, 2), {}};
  EXPECT_EQ(validity_problem(PolygonSet2{a, {square(3, 0, 4, 1), {}}}), "");
  EXPECT_EQ(validity_problem(PolygonSet2{a, {square(2, 2, 3, 3), {}}}), "");  // corner
  EXPECT_EQ(validity_problem(PolygonSet2{a, {{{2, 1}, {3, 0}, {3, 2}}, {}}}), "")
      << "polygons of a set may touch at a point inside an edge";
  EXPECT_NE(validity_problem(PolygonSet2{a, {square(2, 0, 3, 2), {}}}), "");      // shared edge
  EXPECT_NE(validity_problem(PolygonSet2{a, {square(2, 1, 3, 3), {}}}), "");      // part of one
  EXPECT_NE(validity_problem(PolygonSet2{a, {square(1, 1, 3, 3), {}}}), "");      // overlap
  EXPECT_NE(validity_problem(PolygonSet2{a, {square(0.5, 0.5, 1, 1), {}}}), "");  // nested
  const PolygonWithHoles2 frame{square(0, 0, 6, 6), {reversed(square(1, 1, 5, 5))}};
  EXPECT_EQ(validity_problem(PolygonSet2{frame, {square(2, 2, 3, 3), {}}}), "")
      << "an island in a hole";
}

TEST(OracleAreas, IntersectionAndDifferenceWhateverTheOrientation) {
  const PolygonSet2 a{{square(0, 0, 2, 2), {reversed(square(0.5, 0.5, 1, 1))}}};
  const PolygonSet2 b{{square(1, 0, 3, 2), {}}};
  const ExactAreas areas = exact_clip_areas(a, b);
  EXPECT_EQ(areas.subject, 3.75);
  EXPECT_EQ(areas.clip, 4.0);
  EXPECT_EQ(areas.inside, 2.0);
  EXPECT_EQ(areas.outside, 1.75);
  EXPECT_EQ(areas.clip_outside, 2.0);
  const PolygonSet2 a_turned{{reversed(a[0].outer), {a[0].holes[0]}}};
  const ExactAreas turned = exact_clip_areas(a_turned, b);
  EXPECT_EQ(turned.subject, 3.75);
  EXPECT_EQ(turned.inside, 2.0);
  // A multipolygon is the union of its parts.
  EXPECT_EQ(exact_area(PolygonSet2{{square(0, 0, 2, 2), {}}, {square(2, 0, 3, 1), {}}}), 5.0);
}

TEST(OracleAreas, HoleTouchingInsideAnEdge) {
  // Not a valid CGAL Polygon_with_holes_2; the oracle builds it as outer − hole.
  const PolygonSet2 touching{{square(0, 0, 4, 4), {{{2, 0}, {1, 1}, {3, 1}}}}};
  EXPECT_EQ(exact_area(touching), 15.0);
  const ExactAreas areas = exact_clip_areas(touching, {{square(-1, -1, 2, 5), {}}});
  EXPECT_EQ(areas.inside, 7.5);
  EXPECT_EQ(areas.outside, 7.5);
}

TEST(OracleAreas, ExactFarFromTheOrigin) {
  const PolygonSet2 far{{square(1e8, 1e8, 1e8 + 1, 1e8 + 0.5), {}}};
  EXPECT_EQ(exact_area_of_pieces(far), 0.5);
  EXPECT_EQ(exact_area(far), 0.5);
  EXPECT_TRUE(std::isnan(exact_area_of_pieces({{{{0, 0}, {1, 0}, {NAN, 1}}, {}}})));
}

TEST(OracleAreas, SymmetricDifferenceOfTheExactAnswerIsZero) {
  const PolygonSet2 a{{square(0, 0, 2, 2), {}}};
  const PolygonSet2 diamond{{{{1, -0.5}, {2.5, 1}, {1, 2.5}, {-0.5, 1}}, {}}};
  const ExactOverlay overlay(a, diamond);
  EXPECT_EQ(overlay.areas().inside, 3.5);
  const PolygonSet2 octagon{
      {{{0.5, 0}, {1.5, 0}, {2, 0.5}, {2, 1.5}, {1.5, 2}, {0.5, 2}, {0, 1.5}, {0, 0.5}}, {}}};
  EXPECT_EQ(overlay.inside_discrepancy(octagon), 0.0);
  EXPECT_EQ(overlay.inside_discrepancy(a), 0.5);
  EXPECT_EQ(overlay.outside_discrepancy({}), 0.5);
}

TEST(Wkt, ReadsPolygonsAndMultipolygons) {
  const ParsedGeometry polygon = read_wkt(
      "POLYGON(\n (20 20, 20 160, 160 160, 160 20, 20 20),\n (140 140, 40 140, 40 40, "
      "140 40, 140 140))");
  ASSERT_TRUE(polygon.areal);
  ASSERT_EQ(polygon.polygons.size(), 1u);
  EXPECT_EQ(polygon.polygons[0].outer.size(), 4u);
  ASSERT_EQ(polygon.polygons[0].holes.size(), 1u);
  EXPECT_EQ(polygon.polygons[0].holes[0][0], (Point2{140, 140}));

  const ParsedGeometry multi = read_wkt("MULTIPOLYGON (((1 1, 1 5, 5 5, 5 1, 1 1), EMPTY))");
  ASSERT_EQ(multi.polygons.size(), 1u);
  EXPECT_TRUE(multi.polygons[0].holes.empty());

  const ParsedGeometry numbers = read_wkt("POLYGON ((0.1 -2.5e-3, 1E2 0, 6.5105151320986412 1))");
  EXPECT_EQ(numbers.polygons[0].outer[0], (Point2{0.1, -2.5e-3}));
  EXPECT_EQ(numbers.polygons[0].outer[2].x, 6.5105151320986412);
}

TEST(Wkt, EmptyAndOtherTypes) {
  const ParsedGeometry empty = read_wkt(" POLYGON EMPTY ");
  EXPECT_TRUE(empty.areal);
  EXPECT_TRUE(empty.empty);
  EXPECT_TRUE(read_wkt("MULTIPOLYGON EMPTY").empty);
  EXPECT_FALSE(read_wkt("POINT (1 2)").areal);
  EXPECT_FALSE(read_wkt("LINESTRING EMPTY").areal);
  EXPECT_EQ(read_wkt("GEOMETRYCOLLECTION (POINT (1 1))").type, "GEOMETRYCOLLECTION");
  EXPECT_THROW(read_wkt("POLYGON ((0 0, 1 0, 1 1)"), std::runtime_error);
  EXPECT_THROW(read_wkt("POLYGON ((0 0, 1 x, 1 1))"), std::runtime_error);
}

TEST(Wkt, WritesWhatItReads) {
  std::mt19937_64 rng(7);
  const PolygonSet2 polygons{random_polygon_with_holes(rng), random_polygon_with_holes(rng)};
  const ParsedGeometry back = read_wkt(to_wkt(polygons));
  ASSERT_EQ(back.polygons.size(), 2u);
  EXPECT_EQ(back.polygons[0].outer, polygons[0].outer);
  EXPECT_EQ(back.polygons[1].holes, polygons[1].holes);
}

TEST(Wkb, ReadsBothByteOrdersAndTheSridFlag) {
  const char* little =
      "0103000000010000000400000000000000000000000000000000000000000000000000F03F00000000000000"
      "00000000000000F03F000000000000F03F00000000000000000000000000000000";
  ASSERT_TRUE(looks_like_wkb_hex(little));
  const ParsedGeometry polygon = read_wkb_hex(little);
  EXPECT_EQ(polygon.type, "POLYGON");
  ASSERT_EQ(polygon.polygons.size(), 1u);
  EXPECT_EQ(polygon.polygons[0].outer, (Loop2{{0, 0}, {1, 0}, {1, 1}}));
  // Big-endian multipolygon with SRID 4326.
  const ParsedGeometry multi = read_wkb_hex(
      "0020000006000010E60000000100000000030000000100000004000000000000000000000000000000004000"
      "0000000000000000000000000000000000000000000040000000000000000000000000000000000000000000000"
      "0");
  EXPECT_EQ(multi.type, "MULTIPOLYGON");
  ASSERT_EQ(multi.polygons.size(), 1u);
  EXPECT_EQ(multi.polygons[0].outer, (Loop2{{0, 0}, {2, 0}, {0, 2}}));
  EXPECT_FALSE(looks_like_wkb_hex("POLYGON EMPTY"));
  EXPECT_THROW(read_wkb_hex("0103000000"), std::runtime_error);
}

TEST(Generators, DeterministicPerSeed) {
  std::mt19937_64 a(42);
  std::mt19937_64 b(42);
  for (int i = 0; i < 20; ++i) {
    const PolygonWithHoles2 p = random_polygon_with_holes(a);
    const PolygonWithHoles2 q = random_polygon_with_holes(b);
    EXPECT_EQ(p.outer, q.outer);
    EXPECT_EQ(p.holes, q.holes);
    EXPECT_EQ(random_grid_polygon(a).outer, random_grid_polygon(b).outer);
  }
}

TEST(Generators, ValidAndVaried) {
  std::mt19937_64 rng(1);
  int holes = 0;
  for (int i = 0; i < 300; ++i) {
    const PolygonWithHoles2 p = random_polygon_with_holes(rng);
    ASSERT_EQ(validity_problem(oriented({p})), "");
    EXPECT_GE(p.holes.size(), 1u);
    EXPECT_LE(p.holes.size(), 3u);
    holes += static_cast<int>(p.holes.size());
  }
  int grid_holes = 0;
  int diagonal = 0;
  for (int i = 0; i < 300; ++i) {
    const PolygonWithHoles2 p = random_grid_polygon(rng);
    ASSERT_EQ(validity_problem(oriented({p})), "");
    for (const Point2& v : p.outer) {
      ASSERT_EQ(v.x, std::round(v.x));
      ASSERT_GE(v.x, 0);
      ASSERT_LE(v.y, kGridSize);
    }
    grid_holes += p.holes.empty() ? 0 : 1;
    for (std::size_t k = 0; k < p.outer.size(); ++k) {
      const Point2& a = p.outer[k];
      const Point2& b = p.outer[(k + 1) % p.outer.size()];
      diagonal += (a.x != b.x && a.y != b.y) ? 1 : 0;
    }
  }
  EXPECT_GT(holes, 300);
  EXPECT_GT(grid_holes, 30) << "grid polygons should often have holes";
  EXPECT_GT(diagonal, 100) << "snapped stars bring diagonal edges";
  for (int i = 0; i < 100; ++i) {
    const PolygonWithHoles2 sliver = sliver_triangle(rng, 1e-7);
    ASSERT_EQ(validity_problem(oriented({sliver})), "");
    const double area = exact_area({sliver});
    double longest = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      const Point2& a = sliver.outer[k];
      const Point2& b = sliver.outer[(k + 1) % 3];
      longest = std::max(longest, std::hypot(b.x - a.x, b.y - a.y));
    }
    EXPECT_NEAR(2.0 * area / (longest * longest), 1e-7, 1e-9);  // height / base
  }
}

TEST(Generators, ValidityAgreesWithCgal) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 100; ++i) {
    const PolygonWithHoles2 p = oriented({random_polygon_with_holes(rng)})[0];
    EXPECT_TRUE(cgal_accepts(p));
    const PolygonWithHoles2 g = oriented({random_grid_polygon(rng)})[0];
    EXPECT_TRUE(cgal_accepts(g)) << to_wkt({g});
  }
}

TEST(Transforms, TranslateAndScale) {
  const PolygonSet2 unit{{square(0, 0, 1, 1), {}}};
  EXPECT_EQ(translated(unit, {1e6, -2})[0].outer[2], (Point2{1e6 + 1, -1}));
  EXPECT_EQ(scaled(unit, 1e5)[0].outer[2], (Point2{1e5, 1e5}));
  EXPECT_EQ(exact_area(scaled(unit, 0.5)), 0.25);
}

}  // namespace
}  // namespace shadowgen::test
