#include "detail/origin_json.h"

namespace shadowgen::output::detail {

void write_origin(JsonWriter& out, const FaceOrigin& origin) {
  if (origin.empty()) return;
  out.key("origin").begin_object();
  out.key("format").value(origin.format).key("object").value(origin.object);
  out.key("group").value(origin.group).key("semantic").value(origin.semantic);
  out.end_object();
}

}  // namespace shadowgen::output::detail
