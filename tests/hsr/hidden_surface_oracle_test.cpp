// Whole scenes against the oracles (see visibility_check.h): the fragments never overlap
// and cover exactly the union of the images (CGAL, relative error <= 1e-9), at 100,000
// random image points per view the covering fragment belongs to the polygon a brute-force
// ray caster sees nearest, no polygon is lost, and shuffling the input changes no
// polygon's visible area.

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "tests/hsr/scenes.h"
#include "tests/hsr/visibility_check.h"

namespace shadowgen::test {
namespace {

struct SceneCase {
  std::string name;
  Scene (*make)();
};

void PrintTo(const SceneCase& scene_case, std::ostream* out) { *out << scene_case.name; }

const SceneCase kScenes[] = {
    {"triangle_soup", [] { return triangle_soup(101, 80); }},
    {"triangle_soup_dense", [] { return triangle_soup(102, 150); }},
    {"boxes_on_ground", [] { return boxes_on_ground(201, 14); }},
    {"boxes_on_ground_crowded", [] { return boxes_on_ground(202, 30); }},
    {"polygons_with_holes", [] { return polygons_with_holes(301, 14); }},
    {"polygons_with_holes_many", [] { return polygons_with_holes(302, 30); }},
    {"cyclic_sticks", [] { return cyclic_sticks(401, 1); }},
    {"cyclic_sticks_stacked", [] { return cyclic_sticks(402, 4); }},
    {"interpenetrating_quads", [] { return interpenetrating_quads(501, 24); }},
    {"near_plane_cut", [] { return near_plane_cut(601); }},
    {"inside_closed_box", [] { return inside_closed_box(701); }},
};

class HiddenSurfaceOracle : public ::testing::TestWithParam<SceneCase> {};

Scene scene_of(const SceneCase& scene_case) {
  Scene scene = scene_case.make();
  scene.name = scene_case.name;
  return scene;
}

TEST_P(HiddenSurfaceOracle, FragmentsCoverTheImagesAndShowTheNearestPolygon) {
  ExpectVisibilityMatchesOracles(scene_of(GetParam()));
}

TEST_P(HiddenSurfaceOracle, ShuffledInputGivesTheSameVisibleAreas) {
  ExpectOrderIndependent(scene_of(GetParam()), 3, 7);
}

// The image cut into regions settled independently (hsr/image_regions.h): pieces crossing
// a region's side are clipped to each region and merged again, and what each point shows
// is the same.
TEST_P(HiddenSurfaceOracle, RegionsOfTheImageSettledApartGiveTheSameAnswer) {
  VisibilityCheckOptions options;
  options.samples = 20000;
  options.hsr.regions = 9;
  ExpectVisibilityMatchesOracles(scene_of(GetParam()), options);
}

INSTANTIATE_TEST_SUITE_P(Scenes, HiddenSurfaceOracle, ::testing::ValuesIn(kScenes),
                         [](const ::testing::TestParamInfo<SceneCase>& param) {
                           return param.param.name;
                         });

}  // namespace
}  // namespace shadowgen::test
