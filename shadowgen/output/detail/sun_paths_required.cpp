#include "detail/sun_paths_required.h"

#include "shadowgen/model/input_error.h"

namespace shadowgen::output::detail {

void require_sun_paths(const ShadowedScene& shadowed, std::string_view what) {
  if (!shadowed.sun_paths.empty()) return;
  throw InputError(shadowed.scene().file, "",
                   "has no sun path (a `sun` light with from, to and step_min) to report " +
                       std::string(what) + " of");
}

}  // namespace shadowgen::output::detail
