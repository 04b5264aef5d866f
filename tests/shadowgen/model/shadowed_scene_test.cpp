// A shadowed scene holds its rules from construction: a lit table of one row per face and
// one list per light, and a sampled method's estimate of one row per light, one area per
// face (none for an instant of a sun path). A scene that breaks them cannot be built, and
// every change it allows keeps them.

#include "shadowgen/model/shadowed_scene.h"

#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace shadowgen {
namespace {

// Faces "a" and "b" (unit squares), lights "sun" and "lamp"; with `instant`, a third light
// "p@0", an instant of sun path "p".
Scene two_by_two(bool instant = false) {
  Scene scene;
  for (const char* id : {"a", "b"}) {
    scene.faces.push_back({id, {{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {}}}, "x.json"});
  }
  for (const char* id : {"sun", "lamp"}) {
    Light light;
    light.id = id;
    scene.lights.push_back(light);
  }
  if (instant) {
    Light light;
    light.id = "p@0";
    light.sun = SunInstant{"p", "2026-03-21T12:00", 60, 180.0, 30.0};
    scene.lights.push_back(light);
  }
  return scene;
}

// The message of the std::invalid_argument `build` throws; "" where it throws none.
template <class Build>
std::string refusal(const Build& build) {
  try {
    build();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

const Method kRays{MethodKind::kRays, 64};

TEST(ShadowedScene, ALitTableNotShapedFaceByLightCannotBeBuilt) {
  EXPECT_EQ(refusal([] { ShadowedScene(two_by_two(), LitTable(2, 1)); }),
            "ShadowedScene: lit polygons for 2 faces and 1 lights, the scene has 2 and 2");
  EXPECT_EQ(refusal([] { ShadowedScene(two_by_two(), LitTable(1, 2)); }),
            "ShadowedScene: lit polygons for 1 faces and 2 lights, the scene has 2 and 2");
  EXPECT_EQ(refusal([] { ShadowedScene(two_by_two(), LitTable(2, 2)); }), "");
  const ShadowedScene exact(two_by_two(), LitTable(2, 2));
  EXPECT_TRUE(exact.is_exact());
  EXPECT_FALSE(exact.estimate());
  EXPECT_EQ(exact.method(), Method{});
}

TEST(ShadowedScene, AnEstimateNotShapedLightByFaceCannotBeBuilt) {
  const LitTable none(2, 3, std::vector<bool>(3, false));
  EXPECT_EQ(refusal([&] {
              ShadowedScene(two_by_two(true), none, Estimate{kRays, {{1, 0}, {0, 1}}});
            }),
            "ShadowedScene: estimated lit areas for 2 lights, the scene has 3");
  EXPECT_EQ(refusal([&] {
              ShadowedScene(two_by_two(true), none, Estimate{kRays, {{1, 0}, {0}, {}}});
            }),
            "ShadowedScene: estimated lit areas of 1 faces for light 'lamp', the scene has 2");
  // Only an instant of a sun path has no row: its areas are its path's.
  EXPECT_EQ(refusal([&] {
              ShadowedScene(two_by_two(true), none, Estimate{kRays, {{1, 0}, {}, {}}});
            }),
            "ShadowedScene: estimated lit areas of 0 faces for light 'lamp', the scene has 2");
  EXPECT_EQ(refusal([] {
              ShadowedScene(two_by_two(), LitTable(2, 2), Estimate{kRays, {{1, 0}, {0, 1}}});
            }),
            "ShadowedScene: an estimate with lit polygons for light 'sun'");
  EXPECT_EQ(refusal([&] {
              ShadowedScene(two_by_two(true), none, Estimate{Method{}, {{1, 0}, {0, 1}, {}}});
            }),
            "ShadowedScene: an estimate by the exact method");
  const ShadowedScene sampled(two_by_two(true), none, Estimate{kRays, {{1, 0}, {0, 1}, {}}});
  EXPECT_FALSE(sampled.is_exact());
  ASSERT_TRUE(sampled.estimate());
  EXPECT_EQ(sampled.estimate()->method, kRays);
  EXPECT_EQ(sampled.method(), kRays);
  EXPECT_EQ(LitAreas(sampled)(1, 1), 1.0);
}

TEST(ShadowedScene, AFaceAddedKeepsEveryRowInStep) {
  Scene lights_only = two_by_two(true);
  const std::vector<Face> faces = lights_only.faces;
  lights_only.faces.clear();
  ShadowedScene sampled(lights_only, LitTable(0, 3, std::vector<bool>(3, false)),
                        Estimate{kRays, {{}, {}, {}}});
  sampled.add_face(faces[0], {0.25, 0.5, std::nullopt});
  sampled.add_face(faces[1], {1.0, 0.0, std::nullopt});
  EXPECT_EQ(sampled.estimate()->lit_area,
            (std::vector<std::vector<double>>{{0.25, 1.0}, {0.5, 0.0}, {}}));
  EXPECT_EQ(sampled.lit().size(), 2u);
  EXPECT_EQ(refusal([&] { sampled.add_face(faces[0]); }),
            "ShadowedScene::add_face: estimated lit areas for 0 lights, 3 wanted");
  EXPECT_EQ(refusal([&] {
              sampled.add_face(faces[0], {1.0, 1.0, 1.0});
            }),
            "ShadowedScene::add_face: light 'p@0' has an estimated lit area, unlike the faces "
            "before");
  EXPECT_EQ(sampled.scene().faces.size(), 2u);  // nothing added by a refusal

  ShadowedScene exact(lights_only, LitTable(0, 3));
  exact.add_face(faces[0]);
  exact.lit_at(0, 1).push_back({0, faces[0].parts[0]});
  EXPECT_EQ(lit_area(exact.lit().at(0, 1)), 1.0);
  EXPECT_EQ(refusal([&] {
              exact.add_face(faces[1], {1.0, 1.0, std::nullopt});
            }),
            "ShadowedScene::add_face: estimated lit areas for 3 lights, 0 wanted");
}

TEST(ShadowedScene, LightsKeptTakeTheirRowsWithThem) {
  ShadowedScene sampled(two_by_two(true), LitTable(2, 3, std::vector<bool>(3, false)),
                        Estimate{kRays, {{1, 0}, {0, 1}, {}}});
  sampled.keep_lights({false, true, true});
  EXPECT_EQ(sampled.scene().lights.size(), 2u);
  EXPECT_EQ(sampled.scene().lights[0].id, "lamp");
  EXPECT_EQ(sampled.lit().lights(), 2u);
  EXPECT_EQ(sampled.estimate()->lit_area, (std::vector<std::vector<double>>{{0, 1}, {}}));
  EXPECT_EQ(refusal([&] { sampled.keep_lights({true}); }),
            "ShadowedScene::keep_lights: 1 flags for 2 lights");
}

TEST(ShadowedScene, AnEditOfTheSceneCannotBreakItsShape) {
  ShadowedScene exact(two_by_two(), LitTable(2, 2));
  exact.edit_scene([](Scene& scene) { scene.file = "y.json"; });
  EXPECT_EQ(exact.scene().file, "y.json");
  EXPECT_EQ(refusal([&] { exact.edit_scene([](Scene& scene) { scene.faces.emplace_back(); }); }),
            "ShadowedScene::edit_scene: the faces cannot change");
  EXPECT_EQ(refusal([&] { exact.edit_scene([](Scene& scene) { scene.lights.pop_back(); }); }),
            "ShadowedScene: lit polygons for 2 faces and 2 lights, the scene has 2 and 1");
  exact.edit_face(1, [](Face& face) { face.id = "c"; });
  EXPECT_EQ(exact.scene().faces[1].id, "c");
  EXPECT_THROW(exact.edit_face(2, [](Face&) {}), std::out_of_range);
  // A refused edit leaves the faces and lights as they were.
  EXPECT_EQ(exact.scene().faces.size(), 2u);
  EXPECT_EQ(exact.scene().lights.size(), 2u);

  // A light that stops being an instant needs a row of its own.
  ShadowedScene sampled(two_by_two(true), LitTable(2, 3, std::vector<bool>(3, false)),
                        Estimate{kRays, {{1, 0}, {0, 1}, {}}});
  EXPECT_EQ(
      refusal([&] { sampled.edit_scene([](Scene& scene) { scene.lights[2].sun->step_min = 0; }); }),
      "ShadowedScene: estimated lit areas of 0 faces for light 'p@0', the scene has 2");
}

}  // namespace
}  // namespace shadowgen
