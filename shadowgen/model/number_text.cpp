#include "shadowgen/model/number_text.h"

#include <array>
#include <system_error>

namespace shadowgen {

void append_shortest(std::string& out, double value) {
  std::array<char, 32> buffer{};  // 24 characters suffice for any double
  const char* end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
  out.append(buffer.data(), static_cast<std::size_t>(end - buffer.data()));
}

std::string shortest(double value) {
  std::string out;
  append_shortest(out, value);
  return out;
}

std::string number_text(double value, std::chars_format format, int precision) {
  // 64 characters hold most forms; a longer one (fixed, or hundreds of digits asked for)
  // grows the buffer until it fits.
  std::string out(64, '\0');
  for (;;) {
    const std::to_chars_result r =
        std::to_chars(out.data(), out.data() + out.size(), value, format, precision);
    if (r.ec == std::errc()) {
      out.resize(static_cast<std::size_t>(r.ptr - out.data()));
      return out;
    }
    out.resize(2 * out.size());
  }
}

std::optional<double> parse_number(std::string_view token) {
  if (token.starts_with('+')) token.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

std::optional<std::int64_t> parse_integer(std::string_view token) {
  if (token.starts_with('+')) token.remove_prefix(1);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size() || token.empty()) {
    return std::nullopt;
  }
  return value;
}

}  // namespace shadowgen
