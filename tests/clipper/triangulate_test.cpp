// Tests of clipper/triangulate.h: ear clipping of a polygon with holes in its plane chart
// (the split of a non-planar face), checked by orientation and area.

#include "clipper/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <numbers>
#include <random>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen {
namespace {

std::vector<glm::dvec3> jittered_circle(std::size_t n, double radius, double jitter,
                                        std::uint32_t seed, bool clockwise = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<glm::dvec3> loop;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const double r = radius * (1 + u(rng));
    loop.emplace_back(r * std::cos(t), clockwise ? -r * std::sin(t) : r * std::sin(t), 0.0);
  }
  return loop;
}

double signed_area(const clipper::Point2& a, const clipper::Point2& b, const clipper::Point2& c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// Every triangle turns like the outer loop, and their areas add up to the polygon's.
void expect_triangulation(const std::vector<clipper::Loop2>& loops, std::size_t expected_count) {
  const auto triangles = clipper::triangulate(loops);
  ASSERT_TRUE(triangles);
  EXPECT_EQ(triangles->size(), expected_count);
  std::vector<clipper::Point2> all;
  for (const auto& loop : loops) all.insert(all.end(), loop.begin(), loop.end());
  const double sign = clipper::signed_area(loops[0]) > 0 ? 1.0 : -1.0;
  double sum = 0.0;
  for (const auto& t : *triangles) {
    const double a = sign * signed_area(all[t[0]], all[t[1]], all[t[2]]);
    EXPECT_GE(a, 0.0);
    sum += a;
  }
  double expected = std::abs(clipper::signed_area(loops[0]));
  for (std::size_t h = 1; h < loops.size(); ++h)
    expected -= std::abs(clipper::signed_area(loops[h]));
  EXPECT_NEAR(sum, expected, 1e-9 * expected);
}

TEST(Triangulate, ConvexAndConcaveLoopsEitherOrientation) {
  expect_triangulation({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, 2);
  expect_triangulation({{{0, 0}, {0, 4}, {4, 4}, {4, 0}}}, 2);
  // An L and a comb with collinear vertices.
  expect_triangulation({{{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 4}, {0, 4}}}, 4);
  expect_triangulation({{{0, 0},
                         {1, 0},
                         {2, 0},
                         {3, 0},
                         {3, 3},
                         {2, 3},
                         {2, 1},
                         {1, 1},
                         {1, 3},
                         {0, 3},
                         {0, 2},
                         {0, 1}}},
                       10);
}

TEST(Triangulate, HolesAreBridged) {
  const clipper::Loop2 outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  expect_triangulation({outer, {{2, 2}, {2, 4}, {4, 4}, {4, 2}}}, 8);
  // Holes given counter-clockwise too, side by side, one level with another's rightmost
  // vertex.
  expect_triangulation({outer,
                        {{1, 1}, {3, 1}, {3, 3}, {1, 3}},
                        {{5, 1}, {7, 1}, {7, 3}, {5, 3}},
                        {{5, 5}, {8, 5}, {8, 8}, {5, 8}}},
                       4 + 12 + 6 - 2);
  // Clockwise outer loop, triangles come out clockwise.
  expect_triangulation({{{0, 0}, {0, 10}, {10, 10}, {10, 0}}, {{2, 2}, {4, 2}, {4, 4}, {2, 4}}}, 8);
}

TEST(Triangulate, HolesTouchingTheOuterLoopAndEachOther) {
  const clipper::Loop2 outer{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const auto triangles = clipper::triangulate(
      std::vector<clipper::Loop2>{outer, {{0, 5}, {3, 6}, {3, 4}}, {{3, 6}, {5, 8}, {5, 5}}});
  ASSERT_TRUE(triangles);
  expect_triangulation({outer, {{0, 5}, {3, 6}, {3, 4}}, {{3, 6}, {5, 8}, {5, 5}}},
                       triangles->size());
}

TEST(Triangulate, RandomStarsWithGridHoles) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<clipper::Loop2> loops;
    const auto star = jittered_circle(40 + static_cast<std::size_t>(trial), 100, 0.4,
                                      static_cast<std::uint32_t>(trial), trial % 2 == 1);
    clipper::Loop2 outer;
    for (const auto& p : star) outer.push_back({p.x, p.y});
    loops.push_back(outer);
    std::size_t holes = 0;
    for (int i = -2; i <= 1; ++i) {
      for (int j = -2; j <= 1; ++j) {
        if ((rng() & 1) == 0) continue;
        const double x = 10.0 * i + 1;
        const double y = 10.0 * j + 1;
        loops.push_back({{x, y}, {x, y + 7}, {x + 7, y + 7}, {x + 7, y}});
        ++holes;
      }
    }
    expect_triangulation(loops, star.size() + 4 * holes + 2 * holes - 2);
  }
}

}  // namespace
}  // namespace shadowgen
