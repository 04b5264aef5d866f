// The shadow map on a part nearly edge-on to its light: its image is a sliver narrower than
// a texel, so nearly all of its taps fall beside it, on a neighbour rising towards the light
// from the convex edge they share and on the ground far behind it. The part's plane, extended
// to a tap one texel away, runs hundreds of texels behind the sample; followed there without
// a clamp it fell behind the ground, and a wall that nothing shades came out about half in
// shadow at every resolution (shadow_map.h).

#include "shadowgen/sampled/shadow_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "hsr/area.h"
#include "shadowgen/sampled/estimate.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::sampled {
namespace {

// A block 10 high on a 40 × 40 ground, its top [0,10]² at z = 10 and its side towards −x a
// wall leaning out by 0.02 at its foot: the wall's normal is (−1, 0, 0.002) to 1e-5, so the
// sun (almost straight down) and the lamp (high above, a little to −x) meet it at cosines of
// about 0.002 and 0.01. Nothing lies between the wall and either light: it is wholly lit.
const char* const kLeaningWall = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[-20,-20,0],[20,-20,0],[20,20,0],[-20,20,0]]},
    {"id": "top", "outer": [[0,0,10],[10,0,10],[10,10,10],[0,10,10]]},
    {"id": "wall", "outer": [[-0.02,10,0],[-0.02,0,0],[0,0,10],[0,10,10]]}
  ],
  "lights": [
    {"id": "sun", "type": "directional", "direction": [0.0003, 0.0002, -1]},
    {"id": "lamp", "type": "point", "position": [-0.5, 5.3, 60]}
  ]
})";

std::size_t face_index(const Scene& scene, const std::string& id) {
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    if (scene.faces[f].id == id) return f;
  }
  ADD_FAILURE() << "no face " << id;
  return 0;
}

double total(const std::vector<double>& parts) {
  double sum = 0.0;
  for (const double a : parts) sum += a;
  return sum;
}

// The exact lit fraction of face `f` under light `l`.
double exact_fraction(const Scene& scene, std::size_t f, std::size_t l) {
  GenerateOptions options;
  options.threads = 1;
  const ShadowedScene exact = generate_shadows(scene, options).shadowed;
  double lit = 0.0;
  for (std::size_t k = 0; k < scene.faces[f].parts.size(); ++k) {
    lit += hsr::area(polygons_on_part(exact.lit().at(f, l), k));
  }
  return lit / hsr::area(scene.faces[f].parts);
}

TEST(ShadowMapTest, WallNearlyEdgeOnToItsLightIsLit) {
  const Scene scene = parse_scene(kLeaningWall, "leaning_wall.json").scene;
  const std::size_t wall = face_index(scene, "wall");
  const double area = hsr::area(scene.faces[wall].parts);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    // The reference: the exact generator finds the wall wholly lit.
    ASSERT_NEAR(exact_fraction(scene, wall, l), 1.0, 1e-9) << scene.lights[l].id;
    for (const auto& [samples, resolution] : {std::pair{16, 512}, std::pair{64, 2048}}) {
      const Estimator estimator(scene, {MethodKind::kShadowMap, samples, resolution});
      const PartLitAreas areas = estimator.lit_areas(scene.lights[l]);
      // Only the samples within a texel or so of the ground (a hundredth of the wall's
      // height at 512 texels) may be taken for shadowed.
      EXPECT_GT(total(areas[wall]) / area, 0.95)
          << scene.lights[l].id << " at " << samples << " samples, " << resolution << " texels";
    }
  }
}

// The ground in the same scene, with the block's shadow on it: the clamp lifts no shadow.
// On the same sample points as shadow rays, the map may differ only at those within the
// filter's reach of the shadow's edge (3 texels, 0.06, along its 40 or so): a few of the
// 256, each 1/256 of the ground.
TEST(ShadowMapTest, ClampKeepsTheBlocksShadow) {
  const Scene scene = parse_scene(kLeaningWall, "leaning_wall.json").scene;
  const std::size_t ground = face_index(scene, "ground");
  const double area = hsr::area(scene.faces[ground].parts);
  const Estimator map(scene, {MethodKind::kShadowMap, 256, 2048});
  const Estimator rays(scene, {MethodKind::kRays, 256, 0});
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const double by_rays = total(rays.lit_areas(scene.lights[l])[ground]) / area;
    EXPECT_LT(by_rays, 0.95) << scene.lights[l].id;  // the block shades the ground
    EXPECT_NEAR(total(map.lit_areas(scene.lights[l])[ground]) / area, by_rays, 3.0 / 256)
        << scene.lights[l].id;
  }
}

// A groove 0.05 wide and 1 deep in a 40 × 40 ground. Under a sun leaning 0.1 across it,
// its right side (normal (−1, 0, 0.025)) is shaded by the left rim below the depth 0.4, so
// 40 % of it is lit; its left side is turned away. A lamp 30 above and 30 to its west
// leaves a strip of 5 % lit, and sees the side across two faces of its cube (+x and −z).
// In a map of the whole scene the side's image is under two texels wide at 512: a depth
// test there cannot tell its lit strip from the shaded one. Looked up in a map of its own
// at least face_texels(resolution) texels across (shadow_map.h), its error shrinks with
// the resolution as a large face's does.
const char* const kGroove = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "west", "outer": [[-20,-20,0],[-0.025,-20,0],[-0.025,20,0],[-20,20,0]]},
    {"id": "east", "outer": [[0.025,-20,0],[20,-20,0],[20,20,0],[0.025,20,0]]},
    {"id": "left", "outer": [[-0.025,-20,0],[0,-20,-1],[0,20,-1],[-0.025,20,0]]},
    {"id": "right", "outer": [[0,-20,-1],[0.025,-20,0],[0.025,20,0],[0,20,-1]]}
  ],
  "lights": [
    {"id": "sun", "type": "directional", "direction": [0.1, 0, -1]},
    {"id": "lamp", "type": "point", "position": [-30, 0, 30]}
  ]
})";

TEST(ShadowMapTest, AFaceNarrowerThanATexelIsSeenInAMapOfItsOwn) {
  const Scene scene = parse_scene(kGroove, "groove.json").scene;
  const std::size_t right = face_index(scene, "right");
  const double area = hsr::area(scene.faces[right].parts);
  ASSERT_NEAR(exact_fraction(scene, right, 0), 0.4, 1e-9);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    // Shadow rays from the same sample points decide each point exactly: what differs from
    // them is the map's error alone.
    const double by_rays =
        total(Estimator(scene, {MethodKind::kRays, 1024, 0}).lit_areas(scene.lights[l])[right]) /
        area;
    ASSERT_NEAR(by_rays, exact_fraction(scene, right, l), 1.0 / 32) << scene.lights[l].id;
    double previous = 1.0;
    for (const int resolution : {256, 512, 1024, 2048}) {
      const Estimator estimator(scene, {MethodKind::kShadowMap, 1024, resolution});
      const double error =
          std::fabs(total(estimator.lit_areas(scene.lights[l])[right]) / area - by_rays);
      // The face's map is face_texels(resolution) = 4, 8, 16, 32 texels across: the points
      // it decides wrongly lie within half a texel of the shadow's edge. Measured: sun
      // 0.012, 0.0089, 0.0051, 0.0026 (the whole map alone: 0.14, 0.14, 0.098, 0.050);
      // lamp 0.12, 0.041, 0.011, 0.0004 (alone: 0.21, 0.069, 0.023, 0.0037).
      EXPECT_LT(error, 0.5 / face_texels(resolution)) << scene.lights[l].id << ", " << resolution;
      EXPECT_LE(error, previous) << scene.lights[l].id << ", " << resolution;
      previous = error;
    }
  }
}

}  // namespace
}  // namespace shadowgen::sampled
