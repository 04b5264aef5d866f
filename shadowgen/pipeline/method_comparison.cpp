#include "shadowgen/pipeline/method_comparison.h"

#include <chrono>
#include <cmath>
#include <utility>

#include "hsr/area.h"
#include "shadowgen/pipeline/method_run.h"

namespace shadowgen {
namespace {

struct Timed {
  ShadowedScene shadowed;
  double seconds = 0.0;
};

Timed timed_run(const Scene& scene, const Method& method, const GenerateOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ShadowedScene shadowed = shadows_by_method(scene, method_run(method, options)).shadowed;
  const auto end = std::chrono::steady_clock::now();
  return {std::move(shadowed), std::chrono::duration<double>(end - start).count()};
}

// Per face, its area (0: left out of the errors).
std::vector<double> face_areas(const Scene& scene) {
  std::vector<double> areas;
  areas.reserve(scene.faces.size());
  for (const Face& face : scene.faces) areas.push_back(hsr::area(face.parts));
  return areas;
}

}  // namespace

MethodComparison compare_methods(const Scene& scene, std::span<const Method> methods,
                                 GenerateOptions options, ShadowedScene* exact_shadowed,
                                 const std::function<void(const Method&)>& on_trial) {
  options.sun_hours_regions = false;
  options.keep_instant_polygons = false;
  MethodComparison comparison;
  comparison.threads = options.threads;
  const std::vector<double> areas = face_areas(scene);
  const std::size_t lights = scene.lights.size();
  for (const double a : areas) comparison.pairs += a > 0.0 ? lights : 0;

  if (on_trial) on_trial(Method{});
  Timed exact = timed_run(scene, Method{}, options);
  const LitAreas exact_areas(exact.shadowed);
  // Exact fractions once: every trial is compared with them.
  std::vector<double> exact_fraction(areas.size() * lights, 0.0);
  for (std::size_t f = 0; f < areas.size(); ++f) {
    if (areas[f] <= 0.0) continue;
    for (std::size_t l = 0; l < lights; ++l) {
      exact_fraction[f * lights + l] = exact_areas(f, l) / areas[f];
    }
  }
  comparison.trials.push_back({Method{}, exact.seconds});
  for (const Method& method : methods) {
    if (method.exact()) continue;
    if (on_trial) on_trial(method);
    const Timed run = timed_run(scene, method, options);
    const LitAreas estimated(run.shadowed);
    MethodTrial trial{method, run.seconds};
    double sum = 0.0;
    for (std::size_t f = 0; f < areas.size(); ++f) {
      if (areas[f] <= 0.0) continue;
      for (std::size_t l = 0; l < lights; ++l) {
        const double error = std::fabs(estimated(f, l) / areas[f] - exact_fraction[f * lights + l]);
        sum += error;
        if (error > trial.max_error) {
          trial.max_error = error;
          trial.worst_face = f;
          trial.worst_light = l;
        }
      }
    }
    if (comparison.pairs > 0) trial.mean_error = sum / static_cast<double>(comparison.pairs);
    comparison.trials.push_back(trial);
  }
  mark_pareto(comparison.trials, [](const MethodTrial& t) { return t.mean_error; });
  if (exact_shadowed != nullptr) *exact_shadowed = std::move(exact.shadowed);
  return comparison;
}

}  // namespace shadowgen
