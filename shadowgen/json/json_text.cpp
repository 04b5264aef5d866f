#include "shadowgen/json/json_text.h"

#include <array>
#include <charconv>
#include <nlohmann/json.hpp>

#include "shadowgen/model/number_text.h"

namespace shadowgen::json::detail {

void append_json_number(std::string& out, double value) {
  const std::size_t start = out.size();
  append_shortest(out, value);
  if (out.find_first_of(".eEin", start) == std::string::npos) out += ".0";
}

void append_json_string(std::string& out, std::string_view text) {
  bool plain = true;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x80 || c == '"' || c == '\\') {
      plain = false;
      break;
    }
  }
  if (plain) {  // the common case: ASCII ids and paths need no escaping
    out += '"';
    out += text;
    out += '"';
    return;
  }
  out += nlohmann::json(std::string(text))
             .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace shadowgen::json::detail
