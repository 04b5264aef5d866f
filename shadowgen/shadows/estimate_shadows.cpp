#include "shadowgen/shadows/estimate_shadows.h"

#include <cstddef>
#include <utility>
#include <vector>

#include "detail/light_batches.h"
#include "shadowgen/shadows/sun_hours.h"
#include "shadowgen/shadows/sun_path_sums.h"

namespace shadowgen {

GenerateResult estimate_shadows(const Scene& scene, const LitAreaEstimator& estimator,
                                const EstimateOptions& options) {
  GenerateResult result;
  const std::size_t faces = scene.faces.size(), lights = scene.lights.size();
  result.stats.resize(lights);
  Estimate estimate{estimator.method(), std::vector<std::vector<double>>(lights)};
  std::vector<SunPathHours> paths = sun_paths_of(scene);
  SunPathSums sums(scene, paths, /*keep_polygons=*/false, /*regions=*/false, std::nullopt);
  const std::vector<std::size_t> todo = sums.lights_of_run();
  tbb::task_arena arena = shadows::detail::arena_of(options.threads);
  arena.execute([&] {
    shadows::detail::run_lights(
        todo, !paths.empty(), options.on_light_done, result.stats,
        [&](std::size_t l, LightStats&) { return estimator.lit_areas(scene.lights[l]); },
        [&](const std::vector<std::size_t>& batch,
            const std::vector<std::vector<std::vector<double>>>& estimated) {
          sums.add_estimated(batch, estimated);
          for (std::size_t i = 0; i < batch.size(); ++i) {
            const std::size_t l = batch[i];
            if (sums.in_path(l)) continue;
            std::vector<double>& column = estimate.lit_area[l];
            column.assign(faces, 0.0);
            for (std::size_t f = 0; f < faces; ++f) {
              for (const double a : estimated[i].at(f)) column[f] += a;
            }
          }
        });
    sums.finish();
  });
  result.shadowed = ShadowedScene(scene, LitTable(faces, lights, std::vector<bool>(lights, false)),
                                  std::move(estimate));
  result.shadowed.sun_paths = std::move(paths);
  return result;
}

}  // namespace shadowgen
