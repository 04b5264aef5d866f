#pragma once

// shadowgen as a library: exact polygon shadows (Atherton, Weiler and Greenberg 1978) from
// a C++ program. The one header to include; docs/library.md says what each entry point
// does and which of it is stable.
//
//   #include <shadowgen/shadowgen.h>
//
//   shadowgen::api::Shadows shadows = shadowgen::api::load(argv[1]);  // scene or database
//   std::cout << shadowgen::api::report(shadows);                      // the report CSV
//
// Link it with CMake (find_package(shadowgen) and target shadowgen::shadowgen) or
// pkg-config (`pkg-config --cflags --libs shadowgen`).

#include "shadowgen/api/errors.h"      // IWYU pragma: export
#include "shadowgen/api/outputs.h"     // IWYU pragma: export
#include "shadowgen/api/scene.h"       // IWYU pragma: export
#include "shadowgen/api/scene_data.h"  // IWYU pragma: export
#include "shadowgen/api/shadows.h"     // IWYU pragma: export
#include "shadowgen/api/version.h"     // IWYU pragma: export

namespace shadowgen::api {

// SHADOWGEN_VERSION of the library linked, which may differ from the header's.
const char* version();

}  // namespace shadowgen::api
