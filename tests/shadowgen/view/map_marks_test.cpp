// A map's marks (shadowgen/view/map_marks.h): the scale bar's round lengths, and the
// north arrow turned by the site's north axis and by the camera, against hand-computed
// angles.

#include "shadowgen/view/map_marks.h"

#include <gtest/gtest.h>

#include <optional>

namespace shadowgen {
namespace {

TEST(ScaleBar, TheLongestRoundLengthWithinAQuarterOfThePicture) {
  // 800 pixels: at most 200.
  const ScaleBar ten = scale_bar(20, 800, true);
  EXPECT_EQ(ten.length, 10.0);
  EXPECT_EQ(ten.pixels, 200.0);
  EXPECT_EQ(ten.label, "10 m");
  EXPECT_EQ(scale_bar(7, 800, true).length, 20.0);
  EXPECT_EQ(scale_bar(7, 800, true).pixels, 140.0);
  EXPECT_EQ(scale_bar(0.3, 800, false).length, 500.0);
  EXPECT_EQ(scale_bar(0.3, 800, false).label, "500 units");
  EXPECT_EQ(scale_bar(1300, 800, true).length, 0.1);
  EXPECT_EQ(scale_bar(1300, 800, true).label, "0.1 m");
  EXPECT_EQ(scale_bar(2e3, 800, true).length, 0.1);  // 0.1 × 2000 = 200: at the bound
  EXPECT_EQ(scale_bar(2.1e3, 800, true).length, 0.05);
  // Beyond 10^22 the powers of ten are not doubles: the nearest round length within an ulp.
  EXPECT_DOUBLE_EQ(scale_bar(1e-90, 800, false).length, 2e92);
  EXPECT_DOUBLE_EQ(scale_bar(1e90, 800, false).length, 2e-88);
}

Scene site_scene(double north_axis) {
  Scene scene;
  scene.site = Site{51.5, 0.0, 0.0, 0.0, north_axis};
  hsr::Polygon3 floor;
  floor.outer = {{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}};
  scene.faces.push_back({"floor", {floor}, "scene.json", {}});
  return scene;
}

std::optional<double> north_of(const Scene& scene, const Camera& camera) {
  const CameraView view(camera, scene, 800, 600);
  const std::optional<NorthArrow> arrow = north_arrow(scene, camera, view);
  if (!arrow) return std::nullopt;
  return arrow->angle_deg;
}

Camera looking_down(glm::dvec3 up) {
  Camera camera;
  camera.eye = {0, 0, 20};
  camera.target = {0, 0, 0};
  camera.up = up;
  camera.orthographic = true;
  return camera;
}

// True north is (−sin a, cos a, 0). Looking down with +y up it shows at −a; with +x up,
// the picture's right is −y and north shows at atan2(n·(−y), n·x): 270° for a = 0, 240°
// for a = 30.
TEST(NorthArrow, TurnsWithTheNorthAxisAndTheCamera) {
  EXPECT_NEAR(*north_of(site_scene(0), looking_down({0, 1, 0})), 0.0, 1e-12);
  EXPECT_NEAR(*north_of(site_scene(30), looking_down({0, 1, 0})), 330.0, 1e-12);
  EXPECT_NEAR(*north_of(site_scene(-30), looking_down({0, 1, 0})), 30.0, 1e-12);
  EXPECT_NEAR(*north_of(site_scene(0), looking_down({1, 0, 0})), 270.0, 1e-12);
  EXPECT_NEAR(*north_of(site_scene(30), looking_down({1, 0, 0})), 240.0, 1e-12);
  // In perspective from the south, looking north and down at 45°: north is up.
  Camera from_south;
  from_south.eye = {0, -10, 10};
  from_south.target = {0, 0, 0};
  EXPECT_NEAR(*north_of(site_scene(0), from_south), 0.0, 1e-9);
  // From the east, looking west: north is to the right.
  from_south.eye = {10, 0, 10};
  EXPECT_NEAR(*north_of(site_scene(0), from_south), 90.0, 1e-9);
}

TEST(NorthArrow, NoneWithoutASiteOrWhereNorthIsAlongTheLineOfSight) {
  Scene no_site = site_scene(0);
  no_site.site.reset();
  EXPECT_FALSE(north_of(no_site, looking_down({0, 1, 0})).has_value());
  Camera along;
  along.eye = {0, -20, 0};
  along.target = {0, 0, 0};
  along.orthographic = true;
  EXPECT_FALSE(north_of(site_scene(0), along).has_value());
}

}  // namespace
}  // namespace shadowgen
