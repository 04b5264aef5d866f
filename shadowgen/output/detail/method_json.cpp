#include "method_json.h"

#include <cstdint>

#include "shadowgen/database/database_format.h"

namespace shadowgen::output::detail {

void write_method(JsonWriter& out, const Method& method) {
  namespace key = database::key;
  out.key(key::kMethod).begin_object().key(key::kMethodName).value(method_name(method.kind));
  if (!method.exact()) out.key(key::kSamples).value(static_cast<std::uint64_t>(method.samples));
  if (method.kind == MethodKind::kShadowMap) {
    out.key(key::kResolution).value(static_cast<std::uint64_t>(method.resolution));
  }
  out.end_object();
}

}  // namespace shadowgen::output::detail
