#include "cli/number_options.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>
#include <string>

#include "shadowgen/model/coordinate_range.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::cli {

CLI::Validator number_in(const NumberRange& range) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        const std::optional<double> value = parse_number(text);
        if (!value) return "expected a number, got " + text;
        if (const std::optional<std::string> problem = range_problem(*value, range)) {
          return text + " " + *problem;
        }
        return {};
      },
      interval_text(range));
}

std::optional<std::int64_t> whole_number_within(std::string_view text, std::int64_t low,
                                                std::int64_t high) {
  const std::optional<std::int64_t> value = parse_integer(text);
  if (!value || *value < low || *value > high) return std::nullopt;
  return value;
}

CLI::Validator whole_number_in(std::int64_t low, std::int64_t high) {
  const NumberRange range = whole_range(low, high);
  return CLI::Validator(
      [low, high, range](std::string& text) -> std::string {
        const std::optional<std::int64_t> value = parse_integer(text);
        if (!value) return "expected a whole number, got " + text;
        if (*value < low || *value > high) return text + " " + range_rule(range);
        return {};
      },
      interval_text(range));
}

std::optional<glm::dvec3> parse_triple(std::string_view text) {
  glm::dvec3 v(0.0);
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = i < 2 ? text.find(',') : std::string_view::npos;
    if (i < 2 && comma == std::string_view::npos) return std::nullopt;
    const std::optional<double> number = parse_number(text.substr(0, comma));
    if (!number || !std::isfinite(*number)) return std::nullopt;
    v[i] = *number;
    text.remove_prefix(i < 2 ? comma + 1 : text.size());
  }
  return v;
}

CLI::Validator triple() {
  return CLI::Validator(
      [](std::string& text) {
        return parse_triple(text) ? std::string() : "expected X,Y,Z (three numbers), got " + text;
      },
      "X,Y,Z");
}

CLI::Validator point() {
  return CLI::Validator(
      [](std::string& text) {
        const std::optional<glm::dvec3> p = parse_triple(text);
        if (!p) return "expected X,Y,Z (three numbers), got " + text;
        if (glm::any(glm::greaterThan(glm::abs(*p), glm::dvec3(kLargestCoordinate)))) {
          return text + " is outside the supported range (coordinates of magnitude at most " +
                 shortest(kLargestCoordinate) + ")";
        }
        return std::string();
      },
      "X,Y,Z");
}

}  // namespace shadowgen::cli
