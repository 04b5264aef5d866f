#include "shadowgen/pipeline/method_run.h"

#include <stdexcept>
#include <utility>

#include "shadowgen/sampled/estimate.h"

namespace shadowgen {
namespace {

struct RunOf {
  const Scene& scene;
  GenerateResult operator()(const GenerateOptions& options) const {
    return generate_shadows(scene, options);
  }
  GenerateResult operator()(const SampledRun& run) const {
    const sampled::Estimator estimator(scene, run.method);
    return estimate_shadows(scene, estimator, run.options);
  }
};

}  // namespace

GenerateResult shadows_by_method(const Scene& scene, const MethodRun& run) {
  return std::visit(RunOf{scene}, run);
}

MethodRun method_run(const Method& method, GenerateOptions options) {
  if (method.exact()) return options;
  if (options.keep_instant_polygons) {
    throw std::invalid_argument("method_run: a sampled method keeps no lit polygons");
  }
  if (options.shard) {
    throw std::invalid_argument("method_run: a sampled method's run has no shards");
  }
  return SampledRun{method, {options.threads, std::move(options.on_light_done)}};
}

GenerateResult shadows_by_method(Scene&& scene, const MethodRun& run) {
  if (const auto* exact = std::get_if<GenerateOptions>(&run)) {
    return generate_shadows(std::move(scene), *exact);
  }
  return shadows_by_method(std::as_const(scene), run);
}

}  // namespace shadowgen
