#pragma once

// A run's method as the database and the JSON report name it (docs/scene-format.md,
// "Methods"): "method": {"name": "rays", "samples": N}, "resolution": R added for the
// shadow map; {"name": "exact"} alone for the exact method.

#include "shadowgen/json/json_writer.h"
#include "shadowgen/model/method.h"

namespace shadowgen::output::detail {

void write_method(JsonWriter& out, const Method& method);

}  // namespace shadowgen::output::detail
