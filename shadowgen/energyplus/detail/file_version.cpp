#include "detail/file_version.h"

#include <charconv>

namespace shadowgen::energyplus::detail {
namespace {

// The whole of `text` as a number of at most 4 digits.
std::optional<int> small_number(std::string_view text) {
  if (text.empty() || text.size() > 4) return std::nullopt;
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

std::optional<Version> parse_version(std::string_view text) {
  const std::size_t first = text.find('.');
  if (first == std::string_view::npos) return std::nullopt;
  const std::string_view rest = text.substr(first + 1);
  const std::size_t second = rest.find('.');
  const std::optional<int> major = small_number(text.substr(0, first));
  const std::optional<int> minor = small_number(rest.substr(0, second));
  if (!major || !minor) return std::nullopt;
  if (second != std::string_view::npos && !small_number(rest.substr(second + 1))) {
    return std::nullopt;
  }
  return Version{*major, *minor};
}

std::string version_text(Version version) {
  return std::to_string(version.major) + "." + std::to_string(version.minor);
}

}  // namespace shadowgen::energyplus::detail
