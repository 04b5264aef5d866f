// The exact shadow oracle, first against answers computed by hand, then shadowgen's
// generation against the oracle: lit areas and lit regions (the symmetric difference, so
// a misplaced region of the right area fails) within 1e-9 of each face's area.

#include "tests/shadowgen/shadows/shadow_oracle.h"

#include <gtest/gtest.h>

#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/shadows/shadow_check.h"
#include "tests/shadowgen/shadows/shadow_scenes.h"

namespace shadowgen::test {
namespace {

constexpr double kTolerance = 1e-9;

// Exact rationals rounded once: hand-computed answers are matched to a few ulps.
constexpr double kExact = 1e-14;

Scene square_over_ground(const Light& light) {
  Scene scene;
  add_face(scene, "ground", ground(-4, -4, 4, 4));
  add_face(scene, "square", ground(0, 0, 1, 1, 1.0));
  scene.lights.push_back(light);
  return scene;
}

// Ground minus the square [x0, x1] × [y0, y1]: what a hand-made lit region looks like.
hsr::Polygon3 ground_with_hole(double x0, double y0, double x1, double y1) {
  return polygon({{-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}},
                 {{{x0, y0, 0}, {x0, y1, 0}, {x1, y1, 0}, {x1, y0, 0}}});
}

TEST(ShadowOracle, UnitSquareUnderObliqueSun) {
  // The square [0,1]² at z = 1 moves by (0.5, 0.25) per unit of drop.
  const Scene scene = square_over_ground(directional_light("sun", {0.5, 0.25, -1.0}));
  const ShadowOracle oracle(scene);
  EXPECT_NEAR(oracle.lit(0, 0).face_area, 64.0, kExact);
  EXPECT_NEAR(oracle.lit(0, 0).lit_area, 63.0, kExact);
  EXPECT_NEAR(oracle.lit(0, 0).lit_fraction, 63.0 / 64.0, kExact);
  EXPECT_NEAR(oracle.lit(1, 0).lit_area, 1.0, kExact);

  const std::vector<hsr::Polygon3> right = {ground_with_hole(0.5, 0.25, 1.5, 1.25)};
  const LitComparison good = oracle.compare(0, 0, right);
  EXPECT_EQ(good.problem, "");
  EXPECT_EQ(good.symmetric_difference, 0.0);
  EXPECT_NEAR(good.our_union_area, 63.0, kExact);
  EXPECT_EQ(good.outside_face_area, 0.0);

  // The same area in the wrong place: the symmetric difference sees it.
  const std::vector<hsr::Polygon3> misplaced = {ground_with_hole(0.625, 0.25, 1.625, 1.25)};
  const LitComparison bad = oracle.compare(0, 0, misplaced);
  EXPECT_NEAR(bad.our_union_area, 63.0, kExact);
  EXPECT_NEAR(bad.symmetric_difference, 0.25, kExact);

  // The oracle's own polygons read back as the exact region.
  const LitComparison own = oracle.compare(0, 0, oracle.lit_polygons(0, 0));
  EXPECT_EQ(own.symmetric_difference, 0.0);
}

TEST(ShadowOracle, UnitSquareUnderLamp) {
  // From (0.5, 0.5, 2) the square at height 1 doubles in size on the ground.
  const Scene scene = square_over_ground(point_light("lamp", {0.5, 0.5, 2.0}));
  const ShadowOracle oracle(scene);
  EXPECT_NEAR(oracle.lit(0, 0).lit_area, 60.0, kExact);
  const LitComparison c = oracle.compare(0, 0, std::vector{ground_with_hole(-0.5, -0.5, 1.5, 1.5)});
  EXPECT_EQ(c.symmetric_difference, 0.0);
}

TEST(ShadowOracle, OccluderCrossingTheGroundCastsOnlyAboveIt) {
  // A wall through the ground, front side towards -y; light travelling +y and down: the
  // part above the ground casts [0,1]², the part below does not, and the ground shadows
  // the wall's lower half.
  Scene scene;
  add_face(scene, "ground", ground(-4, -4, 4, 4));
  add_face(scene, "wall", polygon({{0, 0, -1}, {1, 0, -1}, {1, 0, 1}, {0, 0, 1}}));
  scene.lights.push_back(directional_light("sun", {0.0, 1.0, -1.0}));
  const ShadowOracle oracle(scene);
  EXPECT_NEAR(oracle.lit(0, 0).lit_area, 63.0, kExact);
  EXPECT_NEAR(oracle.lit(1, 0).face_area, 2.0, kExact);
  EXPECT_NEAR(oracle.lit(1, 0).lit_area, 1.0, kExact);
}

TEST(ShadowOracle, OccluderCrossingTheLampsLevelIsCutByTheCone) {
  // Lamp at height 1; a wall y = 0.5, x in [0.5, 1], z in [0.5, 2]. Its part below the
  // lamp casts {y' >= 1, y' <= x' <= 2y'} (cut by the ground's edge at 4): area 3.5.
  Scene scene;
  add_face(scene, "ground", ground(-4, -4, 4, 4));
  add_face(scene, "wall",
           polygon({{0.5, 0.5, 0.5}, {1.0, 0.5, 0.5}, {1.0, 0.5, 2.0}, {0.5, 0.5, 2.0}}));
  scene.lights.push_back(point_light("lamp", {0.0, 0.0, 1.0}));
  const ShadowOracle oracle(scene);
  EXPECT_NEAR(oracle.lit(0, 0).lit_area, 60.5, kExact);
  EXPECT_NEAR(oracle.lit(1, 0).lit_area, 0.75, kExact);  // its front faces -y: lit
}

TEST(ShadowOracle, SettledEdgeCases) {
  Scene scene;
  add_face(scene, "ground", ground(-4, -4, 4, 4));
  add_face(scene, "overlap", ground(-1, -1, 1, 1));  // coplanar with the ground
  add_face(scene, "level", ground(0.5, 0.5, 1.5, 1.5, 1.0));
  scene.lights.push_back(point_light("below", {0.0, 0.0, -1.0}));
  scene.lights.push_back(point_light("on_plane", {0.0, 0.0, 0.0}));
  scene.lights.push_back(directional_light("grazing", {1.0, 0.0, 0.0}));
  scene.lights.push_back(point_light("level_with", {0.0, 0.0, 1.0}));
  Light near = point_light("near", {0.0, 0.0, 0.5});
  near.range = LightRange{0.0, 0.5, 2.0};  // the ground is at distance 0.5: not beyond
  scene.lights.push_back(near);
  Light short_range = point_light("short", {0.0, 0.0, 0.5});
  short_range.range = LightRange{0.0, 0.25, 2.0};
  scene.lights.push_back(short_range);
  const ShadowOracle oracle(scene);
  // Facing away, light in the plane, directional light parallel to the plane: unlit.
  for (std::size_t light : {0u, 1u, 2u}) {
    EXPECT_EQ(oracle.lit(0, light).lit_area, 0.0) << light;
    EXPECT_EQ(oracle.lit(1, light).lit_area, 0.0) << light;
  }
  // A lamp in the occluder's plane: the occluder blocks nothing and is itself unlit;
  // the coplanar squares do not shadow each other.
  EXPECT_NEAR(oracle.lit(0, 3).lit_area, 64.0, kExact);
  EXPECT_NEAR(oracle.lit(1, 3).lit_area, 4.0, kExact);
  EXPECT_EQ(oracle.lit(2, 3).lit_area, 0.0);
  // range.end exactly at the ground's distance keeps it; the "level" square (1.0 away)
  // is dropped, so it casts nothing either.
  EXPECT_NEAR(oracle.lit(0, 4).lit_area, 64.0, kExact);
  EXPECT_EQ(oracle.lit(2, 4).lit_area, 0.0);
  EXPECT_EQ(oracle.lit(0, 5).lit_area, 0.0);
  EXPECT_EQ(oracle.lit(1, 5).lit_area, 0.0);
}

TEST(ShadowOracle, HolesLetLightThrough) {
  // A horizontal comb with two square holes 1 above the ground, sun straight down: the
  // shadow is the comb itself, holes lit.
  Scene scene;
  add_face(scene, "ground", ground(-4, -4, 4, 4));
  hsr::Polygon3 comb = comb_with_holes(0.0, 0.0, 2.0, 3, 1.0);
  add_face(scene, "comb", comb);
  scene.lights.push_back(directional_light("sun", {0.0, 0.0, -1.0}));
  const ShadowOracle oracle(scene);
  const double comb_area = oracle.lit(1, 0).face_area;
  EXPECT_NEAR(oracle.lit(0, 0).lit_area, 64.0 - comb_area, kExact);
  EXPECT_NEAR(oracle.lit(1, 0).lit_area, comb_area, kExact);
  // 4 minus two gaps between the teeth and two holes, on the 1/64 grid.
  EXPECT_NEAR(comb_area, 4.0 - 2.0 * 0.390625 * 1.328125 - 2.0 * 0.0625, 1e-12);
}

class OracleScenes : public ::testing::TestWithParam<NamedScene> {};

TEST_P(OracleScenes, GeneratedLitRegionsMatchTheExactOnes) {
  const NamedScene& named = GetParam();
  const OracleCheck check = check_against_oracle(named.scene, kTolerance);
  std::printf("[ %-24s ] %s\n", named.name.c_str(), summary(check).c_str());
  EXPECT_GT(check.pairs, 0u);
  EXPECT_EQ(check.failures, 0u) << summary(check) << "\n" << check.report;
}

// The database's contract: lit details are polygons with holes, so every loop simple.
TEST_P(OracleScenes, GeneratedLitLoopsAreSimple) {
  const NamedScene& named = GetParam();
  const OracleCheck check = check_against_oracle(named.scene, kTolerance);
  EXPECT_EQ(check.invalid, 0u) << check.invalid_report;
}

INSTANTIATE_TEST_SUITE_P(Scenes, OracleScenes, ::testing::ValuesIn(oracle_scenes()),
                         [](const auto& p) { return p.param.name; });

}  // namespace
}  // namespace shadowgen::test
