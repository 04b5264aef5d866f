#include "shadowgen/pipeline/method_run.h"

#include <optional>
#include <stdexcept>
#include <utility>

#include "shadowgen/sampled/estimate.h"

namespace shadowgen {

GenerateResult shadows_by_method(const Scene& scene, const Method& method,
                                 GenerateOptions options) {
  if (method.exact()) {
    options.method = method;
    options.estimate = nullptr;
    return generate_shadows(scene, options);
  }
  if (options.keep_instant_polygons) {
    throw std::invalid_argument("shadows_by_method: a sampled method keeps no lit polygons");
  }
  const sampled::Estimator estimator(scene, method);
  options.method = method;
  options.estimate = [&estimator](const Light& light) { return estimator.lit_areas(light); };
  return generate_shadows(scene, options);
}

GenerateResult shadows_by_method(Scene&& scene, const Method& method, GenerateOptions options) {
  if (!method.exact()) return shadows_by_method(std::as_const(scene), method, std::move(options));
  options.method = method;
  options.estimate = nullptr;
  return generate_shadows(std::move(scene), options);
}

}  // namespace shadowgen
