#include "shadowgen/pipeline/sky_method_comparison.h"

#include <chrono>
#include <utility>
#include <vector>

#include "shadowgen/pipeline/method_run.h"
#include "shadowgen/sky/sky_exposure.h"
#include "shadowgen/sky/sky_lights.h"

namespace shadowgen {

sky::SkyComparison compare_sky_methods(const Scene& scene, int subdivisions,
                                       std::span<const Method> methods, GenerateOptions options,
                                       const std::function<void(const Method&)>& on_trial) {
  options.sun_hours_regions = false;
  options.keep_instant_polygons = false;
  const std::vector<sky::SkyPatch> patches = sky::reinhart_patches(subdivisions);
  const Scene lit_by_sky = sky::sky_scene(scene, patches);
  sky::SkyComparison comparison;
  comparison.subdivisions = subdivisions;
  const auto run = [&](const Method& method) {
    if (on_trial) on_trial(method);
    const auto start = std::chrono::steady_clock::now();
    const GenerateResult result = shadows_by_method(lit_by_sky, method_run(method, options));
    const sky::SkyExposure exposure =
        sky::sky_exposure_of(scene, result.shadowed.sun_paths.at(0), 0, patches);
    if (comparison.area.empty()) comparison.area = exposure.area;
    sky::SkyTrial trial;
    trial.method = method;
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      trial.sky_view_factor.push_back(sky::sky_view_factor(exposure, f));
    }
    trial.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    comparison.trials.push_back(std::move(trial));
  };
  run(Method{});
  options.on_light_done = nullptr;  // the sampled trials are counted by name
  for (const Method& method : methods) {
    if (!method.exact()) run(method);
  }
  std::vector<double> mean_error;
  for (std::size_t t = 0; t < comparison.trials.size(); ++t) {
    mean_error.push_back(sky::sky_errors(comparison, t).mean_error);
  }
  mark_pareto(comparison.trials, [&](const sky::SkyTrial& t) {
    return mean_error[static_cast<std::size_t>(&t - comparison.trials.data())];
  });
  return comparison;
}

}  // namespace shadowgen
