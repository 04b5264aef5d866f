// The sampled estimators against the exact generator on hand-made scenes whose lit areas
// are known exactly: what must be exact is (faces out of range or turned away 0, faces with
// nothing over them their area), and what is estimated converges as samples and the map's
// resolution grow, within bounds the sampling justifies.
//
// Error bounds. With stratified samples a point off the shadow boundary is decided right,
// so only the strata the boundary crosses err. A face of area A with N points has strata of
// side about h = √(A/N); a boundary of length L on it crosses about L/h of them (twice that
// allowing for the strata the area-preserving map stretches). At worst each errs by its
// whole area: an error of at most about L·h (kStrata·L·h below). Each errs independently,
// by at most h² and with a standard deviation at most h²/2, so the error's standard
// deviation is at most σ = ½·h²·√(2L/h); the tests take the smaller of the worst case and
// 3σ. The points are the same on every run, so a bound that holds holds for good. A shadow
// map moves and blurs the boundary by up to the filter's reach, 1.5 texels, plus half a
// texel of rasterisation: kTexels·L·w more for texels of width w.

#include "shadowgen/sampled/estimate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "hsr/area.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen::sampled {
namespace {

constexpr double kStrata = 0.5;
constexpr double kTexels = 2.0;

Scene scene_of(const std::string& json) { return parse_scene(json, "test.json").scene; }

Method rays(int samples) { return {MethodKind::kRays, samples, 0}; }
Method shadow_map(int samples, int resolution) {
  return {MethodKind::kShadowMap, samples, resolution};
}

// The exact generator's lit area per part, [light][face][part].
std::vector<PartLitAreas> exact_part_areas(const Scene& scene) {
  GenerateOptions options;
  options.threads = 1;
  const ShadowedScene shadowed = generate_shadows(scene, options).shadowed;
  std::vector<PartLitAreas> out(scene.lights.size());
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      out[l].emplace_back();
      for (std::size_t k = 0; k < scene.faces[f].parts.size(); ++k) {
        out[l][f].push_back(hsr::area(polygons_on_part(shadowed.lit().at(f, l), k)));
      }
    }
  }
  return out;
}

double face_total(const std::vector<double>& parts) {
  double sum = 0.0;
  for (double a : parts) sum += a;
  return sum;
}

double face_area(const Face& face) { return hsr::area(face.parts); }

// Ground [0,10]² in z = 0 and a 4 × 4 roof at z = 1 over [2,6] × [3,7], from hand_scenes.h:
// "down" shades [2,6] × [3,7], "slant" [3,7] × [3,7]; 84 lit either way.
const char* const kRoof = test::kTwoLights;

// The roof with a 2 × 2 hole: 88 of the ground lit.
const char* const kRoofWithHole = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "roof", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]], "holes": [[[3,4,1],[5,4,1],[5,6,1],[3,6,1]]]}
  ],
  "lights": [{"id": "down", "type": "directional", "direction": [0,0,-1]}]
})";

// A concave L-shaped ground ([0,10]² less [5,10]², 75) under a roof over [3,7]² whose shadow
// falls on 12 of it: 63 lit.
const char* const kLUnderRoof = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ell", "outer": [[0,0,0],[10,0,0],[10,5,0],[5,5,0],[5,10,0],[0,10,0]]},
    {"id": "roof", "outer": [[3,3,1],[7,3,1],[7,7,1],[3,7,1]]}
  ],
  "lights": [{"id": "down", "type": "directional", "direction": [0,0,-1]}]
})";

// A lamp 4 above the middle of the ground, a 2 × 2 roof half-way up: its shadow, twice its
// size, [-2,2]², and the tile's, 8/7 its size: 400 − 16 − 64/49 lit. The second lamp's range
// (end 1.5) takes in the ground (1 away) but not the tile at x ∈ [3.5,4.5], z = 0.5, 3.5 away,
// which still shades [7,9] × [-1,1] of it (the spec): 396 of 400. The wall at x = 50 faces that
// lamp, 49 away: beyond range, neither receiving nor (beyond every receiver) occluding.
const char* const kLamps = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[-10,-10,0],[10,-10,0],[10,10,0],[-10,10,0]]},
    {"id": "roof", "outer": [[-1,-1,2],[1,-1,2],[1,1,2],[-1,1,2]]},
    {"id": "tile", "outer": [[3.5,-0.5,0.5],[4.5,-0.5,0.5],[4.5,0.5,0.5],[3.5,0.5,0.5]]},
    {"id": "wall", "outer": [[50,-5,0],[50,-5,5],[50,5,5],[50,5,0]]}
  ],
  "lights": [
    {"id": "lamp", "type": "point", "position": [0,0,4]},
    {"id": "low", "type": "point", "position": [0,0,1],
     "range": {"falloff_start": 1, "end": 1.5, "exponent": 2}}
  ]
})";

// The roof of kRoof turned over (clockwise from above): turned away from the sun, it gets
// nothing and still shades the ground. A wall in the plane x = 8 sees "along" edge-on.
const char* const kTurnedAndEdgeOn = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "under", "outer": [[2,3,1],[2,7,1],[6,7,1],[6,3,1]]},
    {"id": "wall", "outer": [[8,2,0],[8,4,0],[8,4,3],[8,2,3]]}
  ],
  "lights": [
    {"id": "down", "type": "directional", "direction": [0,0,-1]},
    {"id": "along", "type": "directional", "direction": [0,1,-1]}
  ]
})";

// A sun 5 degrees above the horizon, travelling +x, over a ground 40 × 10 and a wall 1 high
// standing on it at x = 2: the wall's shadow reaches 1 / tan 5° ≈ 11.43 along the ground,
// which the sun grazes (no acne may darken it, no bias may lift the shadow off).
const char* const kLowSun = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[40,0,0],[40,10,0],[0,10,0]]},
    {"id": "wall", "outer": [[2,0,0],[2,0,1],[2,10,1],[2,10,0]]}
  ],
  "lights": [{"id": "low", "type": "directional", "direction": [0.99619469809174555,0,-0.087155742747658166]}]
})";
const double kLowSunShadow = 10.0 / std::tan(5.0 * M_PI / 180.0);

struct Case {
  const char* name;
  const char* json;
  std::size_t light, face;
  double exact;     // the known lit area, which the exact generator must give too
  double boundary;  // the shadow boundary's length on the face
  // What a shadow map spans at the face: the scene's box's diagonal for a directional light
  // (its map is fitted to the box seen along the light); for a point light twice the
  // face's farthest distance from it (a cube map's texel at depth z is 2z / R wide).
  double span;
};

// The cases whose estimates must converge.
const Case kCases[] = {
    {"roof, sun straight down", kRoof, 0, 0, 84.0, 16.0, std::sqrt(201.0)},
    {"roof, slanting sun", kRoof, 1, 0, 84.0, 16.0, std::sqrt(201.0)},
    {"roof with a hole", kRoofWithHole, 0, 0, 88.0, 24.0, std::sqrt(201.0)},
    {"L under a roof", kLUnderRoof, 0, 0, 63.0, 12.0, std::sqrt(201.0)},
    {"lamp over a roof", kLamps, 0, 0, 400.0 - 16.0 - 64.0 / 49.0, 16.0 + 32.0 / 7.0,
     2.0 * std::sqrt(216.0)},
    {"ranged lamp, tile beyond range", kLamps, 1, 0, 396.0, 8.0, 2.0 * std::sqrt(201.0)},
    {"turned-over roof", kTurnedAndEdgeOn, 0, 0, 84.0, 16.0, std::sqrt(209.0)},
    {"wall under a low sun", kLowSun, 0, 0, 400.0 - kLowSunShadow, 20.0, std::sqrt(1701.0)},
};

// The sampling error bound of a face of area `area` with `samples` points and a shadow
// boundary `boundary` long (see above).
double sampling_bound(double area, int samples, double boundary) {
  const double h = std::sqrt(area / samples);
  const double sigma = 0.5 * h * h * std::sqrt(2.0 * boundary / h);
  return std::min(kStrata * boundary * h, 3.0 * sigma);
}

double estimate(const Case& c, const Method& method) {
  const Scene scene = scene_of(c.json);
  const Estimator estimator(scene, method);
  return face_total(estimator.lit_areas(scene.lights[c.light])[c.face]);
}

TEST(SampledEstimate, CasesAreExactlyKnown) {
  for (const Case& c : kCases) {
    const Scene scene = scene_of(c.json);
    EXPECT_NEAR(face_total(exact_part_areas(scene)[c.light][c.face]), c.exact, 1e-6) << c.name;
  }
}

TEST(SampledEstimate, RaysConvergeAsSamplesGrow) {
  const int counts[] = {64, 1024, 16384};
  double total[3] = {0, 0, 0};
  for (const Case& c : kCases) {
    const double area = face_area(scene_of(c.json).faces[c.face]);
    for (int i = 0; i < 3; ++i) {
      const double error = std::fabs(estimate(c, rays(counts[i])) - c.exact);
      const double bound = sampling_bound(area, counts[i], c.boundary);
      std::printf("rays %-32s N %6d  error %.5f  bound %.5f\n", c.name, counts[i], error, bound);
      EXPECT_LE(error, bound) << c.name << ", " << counts[i] << " samples";
      total[i] += error;
    }
  }
  EXPECT_LT(total[1], total[0]);
  EXPECT_LT(total[2], total[1]);
}

TEST(SampledEstimate, ShadowMapsConvergeAsResolutionGrows) {
  const int samples = 16384;
  const int resolutions[] = {64, 256, 1024};
  double total[3] = {0, 0, 0};
  for (const Case& c : kCases) {
    const Scene scene = scene_of(c.json);
    const double area = face_area(scene.faces[c.face]);
    for (int i = 0; i < 3; ++i) {
      const double error = std::fabs(estimate(c, shadow_map(samples, resolutions[i])) - c.exact);
      const double texel = c.span / resolutions[i];
      const double bound = sampling_bound(area, samples, c.boundary) + kTexels * c.boundary * texel;
      std::printf("map  %-32s R %5d  error %.5f  bound %.5f\n", c.name, resolutions[i], error,
                  bound);
      EXPECT_LE(error, bound) << c.name << ", resolution " << resolutions[i];
      total[i] += error;
    }
  }
  EXPECT_LT(total[1], total[0]);
  EXPECT_LT(total[2], total[1]);
}

TEST(SampledEstimate, NothingOverAFaceGivesExactlyItsArea) {
  const Scene scene = scene_of(kRoof);
  for (const Method& method : {rays(64), shadow_map(64, 64)}) {
    const Estimator estimator(scene, method);
    for (const Light& light : scene.lights) {
      EXPECT_EQ(estimator.lit_areas(light)[1][0], face_area(scene.faces[1])) << light.id;
    }
  }
  // The ground under the low sun, without the wall: grazed at 5 degrees, and lit whole.
  Scene low = scene_of(kLowSun);
  low.faces.pop_back();
  for (const Method& method : {rays(1024), shadow_map(1024, 256)}) {
    EXPECT_EQ(Estimator(low, method).lit_areas(low.lights[0])[0][0], 400.0);
  }
  // The ground alone under a lamp: lit whole too (its cube map's six faces).
  Scene lamp = scene_of(kLamps);
  lamp.faces.erase(lamp.faces.begin() + 1, lamp.faces.end());
  for (const Method& method : {rays(256), shadow_map(256, 128)}) {
    EXPECT_EQ(Estimator(lamp, method).lit_areas(lamp.lights[0])[0][0], 400.0);
  }
}

TEST(SampledEstimate, TurnedAwayEdgeOnAndOutOfRangeGiveExactlyZero) {
  const Scene turned = scene_of(kTurnedAndEdgeOn);
  const Scene lamps = scene_of(kLamps);
  for (const Method& method : {rays(256), shadow_map(256, 256)}) {
    const Estimator a(turned, method);
    const PartLitAreas down = a.lit_areas(turned.lights[0]);
    EXPECT_EQ(down[1][0], 0.0);  // turned away
    EXPECT_EQ(down[2][0], 0.0);  // a wall under the sun straight down: edge-on
    EXPECT_EQ(a.lit_areas(turned.lights[1])[2][0], 0.0);  // the light along the wall's plane
    const Estimator b(lamps, method);
    const PartLitAreas low = b.lit_areas(lamps.lights[1]);
    EXPECT_EQ(low[1][0], 0.0);  // the roof, 1 above the low lamp: turned away (its back)
    EXPECT_EQ(low[2][0], 0.0);  // the tile beyond range: occludes, receives nothing
    EXPECT_EQ(low[3][0], 0.0);  // the wall beyond range, facing the lamp
    // The lamp without range lights the wall (above the ground, nothing between).
    EXPECT_EQ(b.lit_areas(lamps.lights[0])[3][0], 50.0);
  }
}

TEST(SampledEstimate, EdgeOnWallCastsNoShadow) {
  // The wall of kTurnedAndEdgeOn stands on the ground, touching it along an edge, edge-on
  // to the sun straight down: it shades none of the ground, so all the ground's shadow is
  // the turned-over roof's, and the strip x ∈ [7,10] (no roof over it) is lit whole.
  Scene scene = scene_of(kTurnedAndEdgeOn);
  scene.faces.erase(scene.faces.begin() + 1);  // the roof
  for (const Method& method : {rays(1024), shadow_map(1024, 512)}) {
    EXPECT_EQ(Estimator(scene, method).lit_areas(scene.lights[0])[0][0], 100.0);
  }
}

TEST(SampledEstimate, PartsOfANonPlanarFaceSumToTheFace) {
  // The dart of hand_scenes.h: two triangle parts of √14 each; the roof shades 1/4 of the
  // second.
  const Scene scene = scene_of(test::kDartUnderRoof);
  ASSERT_EQ(scene.faces[0].parts.size(), 2u);
  const PartLitAreas exact = exact_part_areas(scene)[0];
  const double part = std::sqrt(14.0);
  ASSERT_NEAR(exact[0][0], part, 1e-9);
  ASSERT_NEAR(exact[0][1], 0.75 * part, 1e-9);
  for (const Method& method : {rays(4096), shadow_map(4096, 1024)}) {
    const PartLitAreas est = Estimator(scene, method).lit_areas(scene.lights[0]);
    ASSERT_EQ(est[0].size(), 2u);
    EXPECT_EQ(est[0][0], hsr::area(scene.faces[0].parts[0]));  // nothing over the first part
    // The cut across the second part is 1.58 long, 2048 points on it; the map's texels are
    // about 6 / 1024 wide (the dart and roof span 6 across the light).
    const double bound = sampling_bound(part, 2048, 1.6) + kTexels * 1.6 * 6.0 / 1024;
    EXPECT_NEAR(est[0][1], exact[0][1], bound);
    EXPECT_NEAR(est[0][0] + est[0][1], exact[0][0] + exact[0][1], bound);
  }
}

TEST(SampledEstimate, SameLightSameNumbersOnAnyThread) {
  const Scene scene = scene_of(kLamps);
  for (const Method& method : {rays(512), shadow_map(512, 128)}) {
    const Estimator estimator(scene, method);
    std::vector<PartLitAreas> once;
    for (const Light& light : scene.lights) once.push_back(estimator.lit_areas(light));
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      EXPECT_EQ(estimator.lit_areas(scene.lights[l]), once[l]);
    }
    // Four threads, each every light, at once.
    std::vector<std::vector<PartLitAreas>> seen(4);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < 4; ++t) {
      threads.emplace_back([&, t] {
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
          seen[t].push_back(estimator.lit_areas(scene.lights[(l + t) % scene.lights.size()]));
        }
      });
    }
    for (std::thread& thread : threads) thread.join();
    for (std::size_t t = 0; t < 4; ++t) {
      for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        EXPECT_EQ(seen[t][l], once[(l + t) % scene.lights.size()]) << t << " " << l;
      }
    }
    // A second estimator of the same scene: the same numbers again.
    EXPECT_EQ(Estimator(scene, method).lit_areas(scene.lights[1]), once[1]);
  }
}

TEST(SampledEstimate, InvalidMethodsThrow) {
  const Scene scene = scene_of(kRoof);
  EXPECT_THROW(Estimator(scene, Method{}), std::invalid_argument);  // exact
  EXPECT_THROW(Estimator(scene, rays(0)), std::invalid_argument);
  EXPECT_THROW(Estimator(scene, rays(-3)), std::invalid_argument);
  EXPECT_THROW(Estimator(scene, rays(kMaxSamples + 1)), std::invalid_argument);
  EXPECT_THROW(Estimator(scene, shadow_map(16, 0)), std::invalid_argument);
  EXPECT_THROW(Estimator(scene, shadow_map(16, kMaxResolution + 1)), std::invalid_argument);
  EXPECT_THROW(Estimator(scene, shadow_map(0, 16)), std::invalid_argument);
  EXPECT_NO_THROW(Estimator(scene, rays(kMaxSamples)));
  EXPECT_NO_THROW(Estimator(scene, shadow_map(1, 1)));
}

TEST(SampledEstimate, ResultHasEveryFaceAndPart) {
  const Scene scene = scene_of(test::kDartUnderRoof);
  const PartLitAreas areas = Estimator(scene, rays(16)).lit_areas(scene.lights[0]);
  ASSERT_EQ(areas.size(), scene.faces.size());
  for (std::size_t f = 0; f < areas.size(); ++f) {
    EXPECT_EQ(areas[f].size(), scene.faces[f].parts.size());
  }
}

}  // namespace
}  // namespace shadowgen::sampled
