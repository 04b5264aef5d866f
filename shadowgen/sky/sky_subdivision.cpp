#include "shadowgen/sky/sky_subdivision.h"

#include <charconv>

#include "shadowgen/sky/sky_patches.h"

namespace shadowgen::sky {

std::optional<int> subdivisions_named(std::string_view name) {
  if (name == "tregenza") return 1;
  constexpr std::string_view kPrefix = "reinhart:";
  if (!name.starts_with(kPrefix)) return std::nullopt;
  const std::string_view digits = name.substr(kPrefix.size());
  int n = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (error != std::errc() || end != digits.data() + digits.size() || digits.empty() ||
      digits.front() == '+' || n < 1 || n > kMostReinhartSubdivisions) {
    return std::nullopt;
  }
  return n;
}

std::string subdivision_name(int subdivisions) {
  return subdivisions == 1 ? "tregenza" : "reinhart:" + std::to_string(subdivisions);
}

}  // namespace shadowgen::sky
