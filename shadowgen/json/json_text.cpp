#include "shadowgen/json/json_text.h"

#include <array>
#include <charconv>
#include <nlohmann/json.hpp>

namespace shadowgen::detail {

void append_json_number(std::string& out, double value) {
  std::array<char, 32> buffer{};  // 24 characters suffice for any double
  const char* end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
  const std::string_view text(buffer.data(), static_cast<std::size_t>(end - buffer.data()));
  out += text;
  if (text.find_first_of(".eEin") == std::string_view::npos) out += ".0";
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

}  // namespace shadowgen::detail
