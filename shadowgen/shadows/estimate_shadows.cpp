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
  ShadowedScene& shadowed = result.shadowed;
  shadowed.scene = scene;
  shadowed.method = estimator.method();
  const std::size_t faces = scene.faces.size(), lights = scene.lights.size();
  result.stats.resize(lights);
  shadowed.sun_paths = sun_paths_of(scene);
  SunPathSums sums(scene, shadowed.sun_paths, /*keep_polygons=*/false, /*regions=*/false,
                   std::nullopt);
  shadowed.lit = LitTable(faces, lights, std::vector<bool>(lights, false));
  shadowed.estimated_lit_area.resize(lights);
  const std::vector<std::size_t> todo = sums.lights_of_run();
  tbb::task_arena arena = shadows::detail::arena_of(options.threads);
  arena.execute([&] {
    shadows::detail::run_lights(
        todo, !shadowed.sun_paths.empty(), options.on_light_done, result.stats,
        [&](std::size_t l, LightStats&) { return estimator.lit_areas(scene.lights[l]); },
        [&](const std::vector<std::size_t>& batch,
            const std::vector<std::vector<std::vector<double>>>& estimated) {
          sums.add_estimated(batch, estimated);
          for (std::size_t i = 0; i < batch.size(); ++i) {
            const std::size_t l = batch[i];
            if (sums.in_path(l)) continue;
            std::vector<double>& column = shadowed.estimated_lit_area[l];
            column.assign(faces, 0.0);
            for (std::size_t f = 0; f < faces; ++f) {
              for (const double a : estimated[i].at(f)) column[f] += a;
            }
          }
        });
    sums.finish();
  });
  return result;
}

}  // namespace shadowgen
