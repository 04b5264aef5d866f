// Shadows that cannot be computed exactly (generate.h, GenerationError): a clip whose
// snap rounding does not settle fails the generation with an error naming the face and
// the light being worked on, never a lit area that could be wrong. No known input makes
// the snapping give up, so the tests lower its round limit (clipper/clip.h,
// SnapRoundLimitForTesting) until ordinary scenes run into it.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "clipper/clip.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/shadows/light_regions.h"

namespace shadowgen {
namespace {

hsr::Polygon3 square(double x0, double y0, double x1, double y1, double z) {
  return {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, {}};
}

Light sun(std::string id, glm::dvec3 direction) {
  Light light;
  light.id = std::move(id);
  light.direction = direction;
  return light;
}

Light lamp(std::string id, glm::dvec3 position) {
  Light light;
  light.id = std::move(id);
  light.type = LightType::kPoint;
  light.position = position;
  return light;
}

// A ground and an awning over its edge: the awning's shadow crosses the ground's
// boundary, so the ground's lit region takes a clip whose edges cross.
Scene awning_over_an_edge() {
  Scene scene;
  scene.faces.push_back({"ground", {square(0, 0, 10, 10, 0)}, ""});
  scene.faces.push_back({"awning", {square(8, 3, 12, 7, 1)}, ""});
  return scene;
}

GenerateOptions threads(unsigned count) {
  GenerateOptions options;
  options.threads = count;
  return options;
}

TEST(GenerationError, NamesTheFaceAndTheLight) {
  Scene scene = awning_over_an_edge();
  scene.lights.push_back(sun("sun", {0, 0, -1}));
  const clipper::SnapRoundLimitForTesting limit(0);
  try {
    generate_shadows(scene, threads(1));
    FAIL() << "generated shadows with a clip that did not settle";
  } catch (const GenerationError& e) {
    EXPECT_EQ(e.face_id(), "ground");
    EXPECT_EQ(e.light_id(), "sun");
    EXPECT_EQ(e.file(), "");
    EXPECT_NE(e.problem().find("snap rounding"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("face 'ground', light 'sun': ", 0), 0u) << e.what();
  }
}

TEST(GenerationError, NamesTheFaceUnderAPointLight) {
  Scene scene = awning_over_an_edge();
  scene.lights.push_back(lamp("lamp", {9, 5, 4}));
  const clipper::SnapRoundLimitForTesting limit(0);
  try {
    generate_shadows(scene, threads(1));
    FAIL() << "generated shadows with a clip that did not settle";
  } catch (const GenerationError& e) {
    EXPECT_EQ(e.face_id(), "ground") << e.what();
    EXPECT_EQ(e.light_id(), "lamp");
  }
}

// Hidden-surface removal sees only the parts in the light's range, and a face may have
// several parts: the error still names the face the failing part belongs to.
TEST(GenerationError, NamesTheFaceWhenPartsAreLeftOutOfRange) {
  Scene scene;
  scene.faces.push_back({"far", {square(100, 0, 110, 10, 0), square(120, 0, 130, 10, 0)}, ""});
  for (Face& face : awning_over_an_edge().faces) scene.faces.push_back(face);
  Light light = lamp("lamp", {9, 5, 4});
  light.range = LightRange{10.0, 20.0};
  scene.lights.push_back(light);
  const clipper::SnapRoundLimitForTesting limit(0);
  try {
    generate_shadows(scene, threads(1));
    FAIL() << "generated shadows with a clip that did not settle";
  } catch (const GenerationError& e) {
    EXPECT_EQ(e.face_id(), "ground") << e.what();
  }
}

// Lights run in parallel; the error reported is the first light's whatever the threads
// did, so a run names the same light every time.
TEST(GenerationError, TheFirstLightThatFailsIsReported) {
  Scene scene = awning_over_an_edge();
  for (const char* id : {"sun0", "sun1", "sun2", "sun3"})
    scene.lights.push_back(sun(id, {0, 0, -1}));
  const clipper::SnapRoundLimitForTesting limit(0);
  for (int run = 0; run < 5; ++run) {
    try {
      generate_shadows(scene, threads(4));
      FAIL() << "generated shadows with a clip that did not settle";
    } catch (const GenerationError& e) {
      EXPECT_EQ(e.light_id(), "sun0");
      EXPECT_EQ(e.face_id(), "ground");
    }
  }
}

// The limit stops only snapping that still has work to do: a shadow inside the face
// meets no edge of it, and comes out as without the limit.
TEST(GenerationError, ClipsWithNothingToSnapAreUnaffected) {
  Scene scene;
  scene.faces.push_back({"ground", {square(0, 0, 10, 10, 0)}, ""});
  scene.faces.push_back({"table", {square(3, 3, 5, 5, 1)}, ""});
  scene.lights.push_back(sun("sun", {0, 0, -1}));
  const GenerateResult free = generate_shadows(scene, threads(1));
  const clipper::SnapRoundLimitForTesting limit(0);
  const GenerateResult limited = generate_shadows(scene, threads(1));
  ASSERT_EQ(limited.shadowed.lit().size(), 2u);
  for (std::size_t f = 0; f < 2; ++f) {
    EXPECT_DOUBLE_EQ(lit_area(limited.shadowed.lit()[f][0]), lit_area(free.shadowed.lit()[f][0]));
  }
  EXPECT_DOUBLE_EQ(lit_area(limited.shadowed.lit()[0][0]), 96.0);
}

TEST(GenerationError, WithoutTheLimitTheSameScenesGenerate) {
  Scene scene = awning_over_an_edge();
  scene.lights.push_back(sun("sun", {0, 0, -1}));
  scene.lights.push_back(lamp("lamp", {9, 5, 4}));
  const GenerateResult result = generate_shadows(scene, threads(2));
  // The awning's shadow covers [8,10] × [3,7] of the ground.
  EXPECT_DOUBLE_EQ(lit_area(result.shadowed.lit()[0][0]), 92.0);
}

// The partition by light sets (export, render) clips too: where that clip cannot settle,
// the error names the face, with no light to blame.
TEST(GenerationError, LightRegionsNameTheFace) {
  Scene scene = awning_over_an_edge();
  scene.lights.push_back(sun("sun", {0, 0, -1}));
  const ShadowedScene shadowed = generate_shadows(scene, threads(1)).shadowed;
  const clipper::SnapRoundLimitForTesting limit(0);
  try {
    (void)light_regions(shadowed, 0);
    FAIL() << "light-set regions from a clip that did not settle";
  } catch (const GenerationError& e) {
    EXPECT_EQ(e.face_id(), "ground");
    EXPECT_EQ(e.light_id(), "");
    EXPECT_EQ(std::string(e.what()).rfind("face 'ground': light-set regions not computed", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace shadowgen
