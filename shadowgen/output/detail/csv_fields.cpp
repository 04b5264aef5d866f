#include "detail/csv_fields.h"

#include <charconv>

#include "shadowgen/model/number_text.h"

namespace shadowgen::output::detail {

void append_csv_number(std::string& out, double value) {
  out += number_text(value, std::chars_format::general, 17);
}

void append_csv_field(std::string& out, std::string_view field, CsvIds ids) {
  const bool formula =
      !field.empty() && std::string_view("=+-@\t\r").find(field.front()) != std::string_view::npos;
  const std::string_view guard = ids == CsvIds::kSpreadsheetSafe && formula ? "'" : "";
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) {
    out += guard;
    out += field;
    return;
  }
  out += '"';
  out += guard;
  for (const char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

}  // namespace shadowgen::output::detail
