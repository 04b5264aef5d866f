#include "method_json.h"

#include <cstdint>

namespace shadowgen::detail {

void write_method(JsonWriter& out, const Method& method) {
  out.key("method").begin_object().key("name").value(method_name(method.kind));
  if (!method.exact()) out.key("samples").value(static_cast<std::uint64_t>(method.samples));
  if (method.kind == MethodKind::kShadowMap) {
    out.key("resolution").value(static_cast<std::uint64_t>(method.resolution));
  }
  out.end_object();
}

}  // namespace shadowgen::detail
