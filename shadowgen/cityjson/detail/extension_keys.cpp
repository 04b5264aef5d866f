#include "detail/extension_keys.h"

namespace shadowgen::cityjson::detail {

void finish_allowing_extension_keys(JsonObject& object) {
  for (const std::string& key : object.unknown_keys()) {
    if (key.starts_with('+')) object.has(key);
  }
  object.finish();
}

}  // namespace shadowgen::cityjson::detail
