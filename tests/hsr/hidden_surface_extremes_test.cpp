// The oracle checks of hidden_surface_oracle_test.cpp at the extremes: the scenes moved
// 1e6 and 1e8 away from the origin (orthographic views centred on the scene, perspective
// eyes moved with it) and scaled by 1e-4 and 1e5; polygons stacked 1e-9 apart in depth
// or crossing at angles of 1e-9; polygons seen almost edge-on. Each view prints its
// worst errors and the removal's statistics (which show it terminated without runaway
// recursion).

#include <gtest/gtest.h>

#include <iostream>
#include <ostream>
#include <string>
#include <vector>

#include "hsr/hidden_surface.h"
#include "tests/hsr/scenes.h"
#include "tests/hsr/visibility_check.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen::test {
namespace {

struct ExtremeCase {
  std::string name;
  Scene (*make)();
  Placement placement;
};

void PrintTo(const ExtremeCase& extreme_case, std::ostream* out) { *out << extreme_case.name; }

std::vector<ExtremeCase> extreme_cases() {
  const struct {
    const char* name;
    Scene (*make)();
  } scenes[] = {
      {"triangle_soup", [] { return triangle_soup(111, 60); }},
      {"boxes_on_ground", [] { return boxes_on_ground(211, 12); }},
      {"polygons_with_holes", [] { return polygons_with_holes(311, 12); }},
      {"cyclic_sticks", [] { return cyclic_sticks(411, 3); }},
      {"interpenetrating_quads", [] { return interpenetrating_quads(511, 20); }},
      {"near_plane_cut", [] { return near_plane_cut(611); }},
      {"inside_closed_box", [] { return inside_closed_box(711); }},
  };
  const struct {
    const char* name;
    Placement placement;
  } placements[] = {
      {"offset_1e6", {{1e6, -0.75e6, 0.5e6}, 1.0}},
      {"offset_1e8", {{1e8, -0.75e8, 0.5e8}, 1.0}},
      {"scale_1em4", {{0.0, 0.0, 0.0}, 1e-4}},
      {"scale_1e5", {{0.0, 0.0, 0.0}, 1e5}},
  };
  std::vector<ExtremeCase> cases;
  for (const auto& scene : scenes) {
    for (const auto& placement : placements) {
      cases.push_back(
          {std::string(scene.name) + "_" + placement.name, scene.make, placement.placement});
    }
  }
  const Placement identity{};
  const struct {
    const char* name;
    Scene (*make)();
  } special[] = {
      {"near_parallel_1em9", [] { return near_parallel_stack(801, 1e-9); }},
      {"almost_edge_on_axis",
       [] {
         return almost_edge_on(901, {0.0, 0.0, -1.0});
       }},
      {"almost_edge_on_oblique",
       [] {
         return almost_edge_on(902, {0.3, 0.2, -1.0});
       }},
  };
  for (const auto& scene : special) {
    cases.push_back({scene.name, scene.make, identity});
    cases.push_back({std::string(scene.name) + "_scale_1em4", scene.make, {{0, 0, 0}, 1e-4}});
    cases.push_back({std::string(scene.name) + "_scale_1e5", scene.make, {{0, 0, 0}, 1e5}});
  }
  cases.push_back(
      {"almost_edge_on_axis_offset_1e6", special[1].make, {{1e6, -0.75e6, 0.5e6}, 1.0}});
  return cases;
}

class HiddenSurfaceExtremes : public ::testing::TestWithParam<ExtremeCase> {};

TEST_P(HiddenSurfaceExtremes, FragmentsCoverTheImagesAndShowTheNearestPolygon) {
  Scene scene = placed(GetParam().make(), GetParam().placement);
  scene.name = GetParam().name;
  ExpectVisibilityMatchesOracles(scene);
}

TEST_P(HiddenSurfaceExtremes, ShuffledInputGivesTheSameVisibleAreas) {
  Scene scene = placed(GetParam().make(), GetParam().placement);
  scene.name = GetParam().name;
  ExpectOrderIndependent(scene, 2, 7);
}

INSTANTIATE_TEST_SUITE_P(Cases, HiddenSurfaceExtremes, ::testing::ValuesIn(extreme_cases()),
                         [](const ::testing::TestParamInfo<ExtremeCase>& param) {
                           return param.param.name;
                         });

// Nothing stands in front of the fins, so each fin with an image keeps all of it, however
// thin (down to 1e-12 of its height); the fins seen exactly edge-on are counted.
TEST(HiddenSurfaceExtremesFins, SlenderImagesAreKeptWhole) {
  const Scene scene = almost_edge_on(901, {0.0, 0.0, -1.0});
  const hsr::View view = make_view(scene.views[0]);
  const hsr::VisibleSurfaces result = hsr::remove_hidden_surfaces(scene.polygons, view);
  std::cout << describe(result.stats) << '\n';
  EXPECT_EQ(result.stats.edge_on, 2u);
  const std::vector<double> visible = visible_area_by_parent(result, scene.polygons.size());
  for (std::size_t i = 1; i < scene.polygons.size(); ++i) {
    const double image = exact_area_of_pieces(hsr::project_polygon(scene.polygons[i], view));
    std::cout << "fin " << i << ": image area " << image << ", visible " << visible[i] << '\n';
    EXPECT_NEAR(visible[i], image, 1e-9 * image) << "fin " << i;
  }
}

}  // namespace
}  // namespace shadowgen::test
