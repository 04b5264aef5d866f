// Methods run through one per-light loop (shadowgen/pipeline/method_run.h) and compared on a
// scene (method_comparison.h): a sampled method fills the same lit areas the exact one
// does, sun paths included, and the comparison's exact row is the reference.

#include "shadowgen/pipeline/method_comparison.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hsr/area.h"
#include "shadowgen/pipeline/method_run.h"
#include "shadowgen/scene/scene_reader.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

Scene scene_of(const std::string& json) { return parse_scene(json, "test.json").scene; }

TEST(MethodRun, ASampledMethodFillsLitAreasOfPlainLightsAndSunPaths) {
  const Scene scene = scene_of(test::site_scene(test::kCourtyard, test::kMarch21));
  GenerateOptions options;
  options.sun_hours_regions = false;
  const ShadowedScene exact = shadows_by_method(scene, method_run(Method{}, options)).shadowed;
  const ShadowedScene rays =
      shadows_by_method(scene, method_run(Method{MethodKind::kRays, 4096}, options)).shadowed;
  ASSERT_TRUE(rays.estimate());
  EXPECT_EQ(rays.estimate()->method, (Method{MethodKind::kRays, 4096}));
  ASSERT_EQ(rays.sun_paths.size(), 1u);
  const SunPathHours& path = rays.sun_paths.front();
  EXPECT_FALSE(path.regions_kept);
  EXPECT_FALSE(path.lit_polygons_kept);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    EXPECT_FALSE(rays.lit().kept(l));
    EXPECT_TRUE(rays.estimate()->lit_area.at(l).empty());  // every light is an instant
  }
  const LitAreas exact_areas(exact), estimated(rays);
  double worst = 0.0;
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const double area = hsr::area(scene.faces[f].parts);
      worst = std::max(worst, std::fabs(estimated(f, l) - exact_areas(f, l)) / area);
      EXPECT_EQ(estimated(f, l), path.lit_area[f][l]);
    }
  }
  EXPECT_GT(worst, 0.0);   // an estimate, not the exact areas
  EXPECT_LT(worst, 0.01);  // of the face's area, at 4096 points each
}

TEST(MethodRun, PlainLightsKeepTheirEstimatesPerLight) {
  const Scene scene = scene_of(test::kTwoLights);
  const ShadowedScene rays =
      shadows_by_method(scene, SampledRun{Method{MethodKind::kRays, 1024}, {}}).shadowed;
  ASSERT_TRUE(rays.estimate());
  const std::vector<std::vector<double>>& estimated = rays.estimate()->lit_area;
  ASSERT_EQ(estimated.size(), 2u);
  // The ground (100) loses the square's shadow (16) under both lights; the square is lit.
  EXPECT_NEAR(estimated[0][0], 84.0, 0.5);
  EXPECT_NEAR(estimated[1][0], 84.0, 0.5);
  EXPECT_EQ(estimated[0][1], 16.0);
  GenerateOptions keep;
  keep.keep_instant_polygons = true;
  EXPECT_THROW(method_run(Method{MethodKind::kRays, 16}, keep), std::invalid_argument);
}

// What only the exact method makes cannot be asked of a sampled run: its options have no
// such settings, and the exact generator's options take no estimate.
template <class Options>
concept AsksForExactOnly = requires(Options options) {
  options.keep_instant_polygons;
}
|| requires(Options options) { options.sun_hours_regions; }
|| requires(Options options) { options.shard; };
template <class Options>
concept TakesAnEstimate = requires(Options options) {
  options.estimate;
}
|| requires(Options options) { options.method; };
static_assert(AsksForExactOnly<GenerateOptions> && !TakesAnEstimate<GenerateOptions>);
static_assert(!AsksForExactOnly<EstimateOptions> && !TakesAnEstimate<EstimateOptions>);

TEST(MethodRun, ASampledRunOfTheExactMethodIsRefused) {
  const Scene scene = scene_of(test::kTwoLights);
  EXPECT_THROW(shadows_by_method(scene, SampledRun{Method{}, {}}), std::invalid_argument);
  GenerateOptions shard;
  shard.shard = ShardPlace{0, 2};
  EXPECT_THROW(method_run(Method{MethodKind::kRays, 16}, shard), std::invalid_argument);
  EXPECT_TRUE(std::holds_alternative<GenerateOptions>(method_run(Method{}, shard)));
}

TEST(MethodComparison, ExactComesFirstWithoutErrorAndTheFrontIsMarked) {
  const Scene scene = scene_of(test::kTwoLights);
  const std::vector<Method> methods = {
      {MethodKind::kRays, 4}, {MethodKind::kExact}, {MethodKind::kShadowMap, 4096, 1024}};
  std::vector<Method> run;  // in the order they are told, before each runs
  const MethodComparison comparison =
      compare_methods(scene, methods, {}, nullptr, [&run](const Method& m) { run.push_back(m); });
  EXPECT_EQ(run, (std::vector<Method>{Method{}, methods[0], methods[2]}));
  EXPECT_EQ(comparison.pairs, 4u);
  ASSERT_EQ(comparison.trials.size(), 3u);  // the exact one given is the first, not run again
  EXPECT_TRUE(comparison.trials[0].method.exact());
  EXPECT_EQ(comparison.trials[0].mean_error, 0.0);
  EXPECT_EQ(comparison.trials[0].max_error, 0.0);
  EXPECT_TRUE(comparison.trials[0].pareto);  // nothing is more accurate
  for (const MethodTrial& t : {comparison.trials[1], comparison.trials[2]}) {
    EXPECT_GT(t.max_error, 0.0) << method_label(t.method);
    EXPECT_EQ(t.worst_face, 0u) << method_label(t.method);  // the ground: only it is shadowed
    EXPECT_LE(t.mean_error, t.max_error);
    // Beaten by another trial on both counts exactly when not marked.
    bool beaten = false;
    for (const MethodTrial& o : comparison.trials) {
      beaten = beaten || (&o != &t && o.seconds <= t.seconds && o.mean_error <= t.mean_error &&
                          (o.seconds < t.seconds || o.mean_error < t.mean_error));
    }
    EXPECT_EQ(t.pareto, !beaten) << method_label(t.method);
  }
  // Four points on a face of 100 cannot place a 4 × 4 shadow well.
  EXPECT_GT(comparison.trials[1].max_error, comparison.trials[2].max_error);
}

}  // namespace
}  // namespace shadowgen
