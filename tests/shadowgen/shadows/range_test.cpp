// A point light's range drops the faces wholly beyond range.end, never the shadows on a
// face that reaches inside it (docs/scene-format.md, what "lit" means).

#include <gtest/gtest.h>

#include <vector>

#include "hsr/area.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen {
namespace {

// A ground 100 × 10 in z = 0, a lamp 10 above one end, and a wall 5 high across the ground
// at x = 60, 60 from the lamp. Without range, the wall's shadow covers x in [60, 100]
// (the ray over its top reaches the ground at x = 120; sideways it spreads wider than the
// ground): the ground is lit on 600 of its 1000.
Scene ground_lamp_and_far_wall() {
  Scene scene;
  scene.faces.push_back(
      Face{"ground", {hsr::Polygon3{{{0, 0, 0}, {100, 0, 0}, {100, 10, 0}, {0, 10, 0}}, {}}}, "t"});
  scene.faces.push_back(
      Face{"wall", {hsr::Polygon3{{{60, 0, 0}, {60, 10, 0}, {60, 10, 5}, {60, 0, 5}}, {}}}, "t"});
  Light lamp;
  lamp.id = "lamp";
  lamp.type = LightType::kPoint;
  lamp.position = {0, 5, 10};
  scene.lights.push_back(lamp);
  return scene;
}

TEST(Range, AFaceReachingInsideTakesTheShadowsOfOccludersBeyondIt) {
  Scene scene = ground_lamp_and_far_wall();
  const double unranged = lit_area(generate_shadows(scene).shadowed.lit()[0][0]);
  EXPECT_NEAR(unranged, 600.0, 1e-9);

  // range.end 20: the ground reaches inside, the wall (60 away) lies beyond.
  scene.lights[0].range = LightRange{5.0, 20.0, 2.0};
  const GenerateResult ranged = generate_shadows(scene);
  EXPECT_NEAR(lit_area(ranged.shadowed.lit()[0][0]), unranged, 1e-9);
  EXPECT_TRUE(ranged.shadowed.lit()[1][0].empty());  // the wall receives nothing
  EXPECT_EQ(ranged.stats[0].faces_considered, 1u);
  EXPECT_EQ(ranged.stats[0].faces_culled_range, 1u);
}

TEST(Range, FacesBeyondEveryReceiverAreLeftOut) {
  Scene scene = ground_lamp_and_far_wall();
  // Only a small ground near the lamp: its farthest vertex is nearer than the wall, so the
  // wall can shadow nothing in range and the ground is lit whole.
  scene.faces[0].parts[0] = hsr::Polygon3{{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}, {}};
  scene.lights[0].range = LightRange{5.0, 20.0, 2.0};
  const GenerateResult r = generate_shadows(scene);
  EXPECT_NEAR(lit_area(r.shadowed.lit()[0][0]), 100.0, 1e-12);
  EXPECT_TRUE(r.shadowed.lit()[1][0].empty());
}

}  // namespace
}  // namespace shadowgen
