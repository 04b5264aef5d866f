#include "detail/sun_paths_required.h"

#include <string>

#include "shadowgen/model/input_error.h"

namespace shadowgen::detail {

void require_sun_paths(const ShadowedScene& shadowed, std::string_view what) {
  if (!shadowed.sun_paths.empty()) return;
  const Scene& scene = shadowed.scene;
  const std::string file = scene.faces.empty() ? "" : scene.faces.front().source_file;
  throw InputError(file, "",
                   "has no sun path (a `sun` light with from, to and step_min) to report " +
                       std::string(what) + " of");
}

}  // namespace shadowgen::detail
