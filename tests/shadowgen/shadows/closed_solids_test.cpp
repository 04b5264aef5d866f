// Closed solids (shadowgen/shadows/detail/closed_solids.h): which surfaces count as
// closed, embedded and outward, which of their parts a light need not have occlude, and
// that leaving those parts out changes no lit area, on the oracle's scenes and on solids
// made to be awkward (concave, touching, pierced, turned inside out, a lamp inside).

#include "shadowgen/shadows/detail/closed_solids.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "hsr/area.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/detail/face_parts.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/shadows/shadow_check.h"
#include "tests/shadowgen/shadows/shadow_scenes.h"

namespace shadowgen::test {
namespace {

using glm::dvec3;

// The solid of each face's first part, in scene order.
std::vector<int> solids_of(const Scene& scene) {
  const shadows::detail::FaceParts parts = shadows::detail::flatten(scene);
  const shadows::detail::ClosedSolids solids(parts);
  std::vector<int> out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts.owners[i].part == 0) out.push_back(solids.solid(i));
  }
  return out;
}

// The faces whose parts all need not occlude `light`, by id.
std::vector<std::string> left_out(const Scene& scene, const Light& light) {
  const shadows::detail::FaceParts parts = shadows::detail::flatten(scene);
  const shadows::detail::ClosedSolids solids(parts);
  const std::vector<char> out = solids.need_not_occlude(light);
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (out[i]) ids.push_back(scene.faces[parts.owners[i].face].id);
  }
  return ids;
}

// A unit cube's twelve triangles, front sides out, with corner `moved` (of the eight,
// numbered by their bits x, y, z) put at `to`.
Scene triangulated_cube(int moved = -1, dvec3 to = {}) {
  dvec3 c[8];
  for (int k = 0; k < 8; ++k) c[k] = {double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)};
  if (moved >= 0) c[moved] = to;
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  Scene scene;
  for (int f = 0; f < 6; ++f) {
    const int* q = quads[f];
    const std::string name = std::string(1, 'q') + std::to_string(f);
    add_face(scene, name + 'a', polygon({c[q[0]], c[q[1]], c[q[2]]}));
    add_face(scene, name + 'b', polygon({c[q[0]], c[q[2]], c[q[3]]}));
  }
  return scene;
}

TEST(ClosedSolids, ClosedOutwardBoxesAreSolidsAndNothingElseIs) {
  Scene two;
  add_box(two, "a", {});
  add_box(two, "b", {.cx = 3.0});
  EXPECT_EQ(solids_of(two), (std::vector<int>{0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1}));

  Scene open;
  add_box(open, "a", {.with_bottom = false});
  EXPECT_EQ(solids_of(open), std::vector<int>(5, -1));
  // A room, faces turned inward: its volume is negative.
  Scene room;
  add_box(room, "a", {.inward = true});
  EXPECT_EQ(solids_of(room), std::vector<int>(6, -1));
  // Boxes that cross each other are two closed surfaces, each embedded: two solids.
  Scene crossing;
  add_box(crossing, "a", {});
  add_box(crossing, "b", {.cx = 0.5, .cy = 0.5, .base = 0.5});
  EXPECT_EQ(solids_of(crossing)[0], 0);
  EXPECT_EQ(solids_of(crossing)[6], 1);
  // A box standing on another shares no edge: each is a solid of its own, touching the
  // other along a face (which the test within one surface does not look at).
  EXPECT_EQ(solids_of(triangulated_cube()), std::vector<int>(12, 0));

  // A cone of many sides crowds thousands of triangles around its apex, past the budget
  // of pairs looked at for contacts: no solid, and its parts simply occlude. Of few
  // sides, a solid.
  for (const int sides : {12, 4000}) {
    Scene cone;
    hsr::Loop3 base;
    for (int k = 0; k < sides; ++k) {
      const double angle = -2.0 * M_PI * k / sides;
      base.push_back({std::cos(angle), std::sin(angle), 0.0});
    }
    add_face(cone, "base", polygon(base));
    for (int k = 0; k < sides; ++k) {
      add_face(cone, "side", polygon({base[(k + 1) % sides], base[k], {0, 0, 2}}));
    }
    EXPECT_EQ(solids_of(cone)[0], sides == 12 ? 0 : -1) << sides;
  }
}

TEST(ClosedSolids, SurfacesThatTouchOrCrossThemselvesOrTurnInsideOutAreNot) {
  // A corner pushed through the cube to beyond the opposite one: the triangles around it
  // pierce the faces across.
  EXPECT_EQ(solids_of(triangulated_cube(7, {-0.5, -0.25, -0.125})), std::vector<int>(12, -1));
  // A corner pushed onto the opposite face's inside: the surface touches itself there.
  EXPECT_EQ(solids_of(triangulated_cube(7, {0.5, 0.25, 0.0})), std::vector<int>(12, -1));
  // Pushed inward but clear of every other face: still a solid, concave.
  EXPECT_EQ(solids_of(triangulated_cube(7, {0.5, 0.5, 0.5})), std::vector<int>(12, 0));
  // A face run the wrong way round: its edges run as its neighbours' do.
  Scene flipped = triangulated_cube();
  std::reverse(flipped.faces[3].parts[0].outer.begin(), flipped.faces[3].parts[0].outer.end());
  EXPECT_EQ(solids_of(flipped), std::vector<int>(12, -1));
  // A face split along an edge its neighbour does not have (a T-junction).
  Scene split;
  add_box(split, "a", {});
  split.faces[1].parts[0].outer.insert(split.faces[1].parts[0].outer.begin() + 1,
                                       dvec3{0.0, -0.5, 1.0});
  EXPECT_EQ(solids_of(split), std::vector<int>(6, -1));
}

TEST(ClosedSolids, TheLightMustBeOutsideAndThePartTurnedAwayFromIt) {
  Scene box;
  add_box(box, "b", {});  // [-0.5, 0.5]² × [0, 1]
  // Straight down: the sides see it edge-on and stay; the bottom is turned away.
  EXPECT_EQ(left_out(box, directional_light("sun", {0, 0, -1})),
            std::vector<std::string>{"b.bottom"});
  EXPECT_EQ(left_out(box, directional_light("sun", {0.25, 0.5, -1})),
            (std::vector<std::string>{"b.bottom", "b.x1", "b.y1"}));
  // Above the middle: the sides are turned away too (the lamp is inside their slab).
  EXPECT_EQ(left_out(box, point_light("lamp", {0, 0, 3})),
            (std::vector<std::string>{"b.bottom", "b.y0", "b.x1", "b.y1", "b.x0"}));
  EXPECT_EQ(left_out(box, point_light("lamp", {2, 0, 0.5})),
            (std::vector<std::string>{"b.bottom", "b.top", "b.y0", "b.y1", "b.x0"}));
  // Inside, on a face, on an edge, at a corner: nothing.
  for (const dvec3& p : {dvec3{0, 0, 0.5}, dvec3{0, 0, 1}, dvec3{0.5, 0, 1}, dvec3{0.5, 0.5, 1}}) {
    EXPECT_EQ(left_out(box, point_light("lamp", p)), std::vector<std::string>{}) << p.x << p.z;
  }
  // In the plane of the top, beside the box: the top sees it edge-on and stays.
  EXPECT_EQ(left_out(box, point_light("lamp", {3, 0, 1})),
            (std::vector<std::string>{"b.bottom", "b.y0", "b.y1", "b.x0"}));
}

// Lit areas with the backs of solids left out and kept, face by face and light by light.
void ExpectSameLitAreas(const Scene& scene, std::size_t least_left_out) {
  GenerateOptions keep;
  keep.leave_out_solids_backs = false;
  const GenerateResult with = generate_shadows(scene);
  const GenerateResult without = generate_shadows(scene, keep);
  std::size_t left_out = 0;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    left_out += with.stats[l].faces_behind_solids;
    EXPECT_EQ(without.stats[l].faces_behind_solids, 0u);
    EXPECT_EQ(with.stats[l].faces_facing_away, without.stats[l].faces_facing_away);
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      const double area = hsr::area(scene.faces[f].parts);
      EXPECT_NEAR(lit_area(with.shadowed.lit()[f][l]), lit_area(without.shadowed.lit()[f][l]),
                  1e-12 * std::max(area, 1.0))
          << scene.faces[f].id << ", " << scene.lights[l].id;
    }
  }
  EXPECT_GE(left_out, least_left_out);
}

TEST(ClosedSolids, LeavingTheBacksOutChangesNoLitArea) {
  for (const NamedScene& named : oracle_scenes()) {
    SCOPED_TRACE(named.name);
    ExpectSameLitAreas(named.scene, 0);
  }
  ExpectSameLitAreas(boxes_on_ground_sun().scene, 1);
  ExpectSameLitAreas(boxes_on_ground_lamp().scene, 1);

  // A concave solid (the cube with a corner pushed in) over a ground, under a sun and a
  // lamp that cast the solid's own shadow into its hollow.
  Scene hollow = triangulated_cube(7, {0.5, 0.5, 0.5});
  add_face(hollow, "ground", ground(-3, -3, 4, 4, -0.5));
  hollow.lights.push_back(directional_light("sun", {0.3, 0.45, -1}));
  hollow.lights.push_back(point_light("lamp", {2.5, 1.75, 2.25}));
  ExpectSameLitAreas(hollow, 4);

  // A lamp inside a closed box over a ground: every face of the box is turned away from
  // it and every one shadows the ground, so none may be left out.
  Scene lantern;
  add_box(lantern, "box", {.sx = 2.0, .sy = 2.0, .height = 2.0, .base = 0.5});
  add_face(lantern, "ground", ground(-4, -4, 4, 4));
  lantern.lights.push_back(point_light("lamp", {0.25, -0.25, 1.5}));
  ExpectSameLitAreas(lantern, 0);
  // The cube with a corner pushed through it, under a sun: parts turned away from the sun
  // stick out past the front ones, so they must shadow the ground.
  for (const dvec3& to : {dvec3{-0.5, -0.25, -0.125}, dvec3{-0.375, 0.625, 0.5}}) {
    Scene pierced = triangulated_cube(7, to);
    add_face(pierced, "ground", ground(-3, -3, 4, 4, -1.0));
    add_face(pierced, "wall", polygon({{-2, -3, -1}, {-2, 4, -1}, {-2, 4, 3}, {-2, -3, 3}}));
    pierced.lights.push_back(directional_light("sun", {0.2, 0.1, -1}));
    pierced.lights.push_back(directional_light("low", {-1, -0.6, -0.3}));
    pierced.lights.push_back(directional_light("west", {-1, 0.1, 0.05}));
    pierced.lights.push_back(point_light("lamp", {2.5, 0.5, 0.5}));
    ExpectSameLitAreas(pierced, 0);
  }

  // The pergola's closed beams and slats.
  const std::filesystem::path pergola =
      std::filesystem::path(SHADOWGEN_EXAMPLES_DIR) / "scenes" / "pergola.json";
  ExpectSameLitAreas(read_scene(pergola).scene, 10);
}

// Left out or not, the lit regions are the exact ones: a concave solid and crossing
// boxes against CGAL's.
TEST(ClosedSolids, LitRegionsWithTheBacksLeftOutMatchTheOracle) {
  Scene scene = triangulated_cube(7, {0.5, 0.5, 0.5});
  add_box(scene, "a", {.cx = 2.0, .cy = 0.5, .sx = 1.0, .sy = 0.75, .height = 1.5});
  add_box(scene, "b", {.cx = 2.25, .cy = 0.75, .sx = 0.5, .sy = 1.5, .height = 0.75, .base = 0.5});
  add_face(scene, "ground", ground(-3, -3, 5, 5, -0.25));
  scene.lights.push_back(directional_light("sun", {-0.4, 0.3, -1}));
  scene.lights.push_back(point_light("lamp", {3.5, -1.5, 2.5}));
  const OracleCheck check = check_against_oracle(scene, 1e-9);
  EXPECT_EQ(check.failures, 0u) << check.report;
  EXPECT_EQ(check.invalid, 0u) << check.invalid_report;
}

}  // namespace
}  // namespace shadowgen::test
