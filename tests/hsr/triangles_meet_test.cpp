// Exact contact tests of triangles in space (hsr/triangles_meet.h) against CGAL's exact
// intersection of Triangle_3: hand-made touching, crossing and coplanar cases, and random
// triangles on a coarse grid, whose corners are shared often and whose contacts are
// nearly all degenerate (a corner on a side, sides along sides, coplanar overlaps).

#include "hsr/triangles_meet.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "tests/support/cgal_oracle.h"

namespace shadowgen::hsr {
namespace {

using glm::dvec3;

std::vector<dvec3> common_corners(const Triangle3& a, const Triangle3& b) {
  std::vector<dvec3> common;
  for (const dvec3& p : a) {
    for (const dvec3& q : b) {
      if (p == q) common.push_back(p);
    }
  }
  return common;
}

TEST(TrianglesMeet, HandMadeContacts) {
  const Triangle3 floor = {dvec3{0, 0, 0}, dvec3{4, 0, 0}, dvec3{0, 4, 0}};
  // Apart, above.
  EXPECT_FALSE(triangles_meet(floor, {dvec3{0, 0, 1}, dvec3{4, 0, 1}, dvec3{0, 4, 1}}));
  // Standing on the floor with one corner inside it: touching at a point.
  EXPECT_TRUE(triangles_meet(floor, {dvec3{1, 1, 0}, dvec3{1, 1, 3}, dvec3{2, 1, 3}}));
  // Piercing it.
  EXPECT_TRUE(triangles_meet(floor, {dvec3{1, 1, -1}, dvec3{1, 1, 1}, dvec3{2, 2, 1}}));
  // Coplanar, apart, and coplanar, one inside the other.
  EXPECT_FALSE(triangles_meet(floor, {dvec3{3, 3, 0}, dvec3{5, 3, 0}, dvec3{3, 5, 0}}));
  EXPECT_TRUE(triangles_meet(floor, {dvec3{1, 1, 0}, dvec3{2, 1, 0}, dvec3{1, 2, 0}}));

  // Neighbours across an edge: in a fold, coplanar on opposite sides, and folded back
  // onto each other.
  const Triangle3 fold = {dvec3{4, 0, 0}, dvec3{0, 0, 0}, dvec3{2, 0, 3}};
  EXPECT_FALSE(triangles_overlap_beyond_shared(floor, fold));
  EXPECT_FALSE(
      triangles_overlap_beyond_shared(floor, {dvec3{4, 0, 0}, dvec3{0, 0, 0}, dvec3{2, -3, 0}}));
  EXPECT_TRUE(
      triangles_overlap_beyond_shared(floor, {dvec3{4, 0, 0}, dvec3{0, 0, 0}, dvec3{1, 1, 0}}));
  // Neighbours at a corner: apart but there, and one lying on the other from the corner.
  EXPECT_FALSE(
      triangles_overlap_beyond_shared(floor, {dvec3{0, 0, 0}, dvec3{-1, -2, 1}, dvec3{-2, -1, 1}}));
  EXPECT_TRUE(
      triangles_overlap_beyond_shared(floor, {dvec3{0, 0, 0}, dvec3{1, 1, 0}, dvec3{1, 1, 2}}));
  // The same triangle twice.
  EXPECT_TRUE(triangles_overlap_beyond_shared(floor, {floor[2], floor[0], floor[1]}));
  EXPECT_TRUE(degenerate({dvec3{0, 0, 0}, dvec3{1, 1, 1}, dvec3{3, 3, 3}}));
  EXPECT_FALSE(degenerate(floor));
}

// Corners drawn from a 4 × 4 × 4 grid (sometimes flattened to one plane, where the test
// is also told so): against CGAL, both tests, with the corners the triangles happen to
// share.
TEST(TrianglesMeet, RandomGridTrianglesAgreeWithCgal) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> coordinate(0, 3);
  int meeting = 0, sharing = 0, tested = 0;
  for (int trial = 0; tested < 6000; ++trial) {
    const bool flat = trial % 3 == 0;
    auto corner = [&] {
      return dvec3(coordinate(rng), coordinate(rng), flat ? 1.0 : coordinate(rng));
    };
    const Triangle3 a = {corner(), corner(), corner()}, b = {corner(), corner(), corner()};
    if (degenerate(a) || degenerate(b)) continue;
    ++tested;
    const std::vector<dvec3> common = common_corners(a, b);
    const bool meet = test::exact_triangles_share_more_than(a, b, {});
    ASSERT_EQ(triangles_meet(a, b), meet) << trial;
    const bool overlap = common.size() >= 3 || test::exact_triangles_share_more_than(a, b, common);
    ASSERT_EQ(triangles_overlap_beyond_shared(a, b), overlap) << trial;
    // In one plane, the same answer settled in the plane alone.
    if (flat) {
      ASSERT_EQ(triangles_overlap_beyond_shared(a, b, true), overlap) << trial;
    }
    meeting += meet;
    sharing += !common.empty();
  }
  // The draw exercises both answers and shared corners.
  EXPECT_GT(meeting, 1000);
  EXPECT_LT(meeting, 5500);
  EXPECT_GT(sharing, 500);
}

}  // namespace
}  // namespace shadowgen::hsr
