// The shadow map on a part nearly edge-on to its light: its image is a sliver narrower than
// a texel, so nearly all of its taps fall beside it, on a neighbour rising towards the light
// from the convex edge they share and on the ground far behind it. The part's plane, extended
// to a tap one texel away, runs hundreds of texels behind the sample; followed there without
// a clamp it fell behind the ground, and a wall that nothing shades came out about half in
// shadow at every resolution (shadow_map.h).

#include <gtest/gtest.h>

#include <cstddef>
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

TEST(ShadowMapTest, WallNearlyEdgeOnToItsLightIsLit) {
  const Scene scene = parse_scene(kLeaningWall, "leaning_wall.json").scene;
  const std::size_t wall = face_index(scene, "wall");
  const double area = hsr::area(scene.faces[wall].parts);
  GenerateOptions options;
  options.threads = 1;
  const ShadowedScene exact = generate_shadows(scene, options).shadowed;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    // The reference: the exact generator finds the wall wholly lit.
    double exact_lit = 0.0;
    for (std::size_t k = 0; k < scene.faces[wall].parts.size(); ++k) {
      exact_lit += hsr::area(polygons_on_part(exact.lit.at(wall, l), k));
    }
    ASSERT_NEAR(exact_lit / area, 1.0, 1e-9) << scene.lights[l].id;
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

}  // namespace
}  // namespace shadowgen::sampled
