#include "shadowgen/database/database_format.h"

namespace shadowgen::database {

std::optional<Layout> layout_of(std::string_view format) {
  if (format == kIndexedFormat) return Layout::kIndexed;
  if (format == kInlineFormat) return Layout::kInline;
  return std::nullopt;
}

}  // namespace shadowgen::database
