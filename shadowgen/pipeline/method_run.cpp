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

}  // namespace shadowgen
