#include "detail/object_fields.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "shadowgen/model/input_error.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::energyplus::detail {
namespace {

bool same_text(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

}  // namespace

int decimals_of(double value) {
  const std::string text = shortest(value);
  const std::size_t exponent_at = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, exponent_at);
  int exponent = 0;
  if (exponent_at != std::string::npos) {
    exponent = static_cast<int>(*parse_integer(text.substr(exponent_at + 1)));
  }
  const std::size_t point = mantissa.find('.');
  int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
  if (point == std::string::npos) {
    // Trailing zeros of a whole number are not decimals written: 1200 is 1.2e3.
    std::size_t zeros = 0;
    while (zeros + 1 < mantissa.size() && mantissa[mantissa.size() - 1 - zeros] == '0') ++zeros;
    decimals = -static_cast<int>(zeros);
  }
  return decimals - exponent;
}

std::string ObjectFields::described() const {
  std::string out(object_.spec->name);
  if (object_.spec->named) out += " '" + object_.name + "'";
  return out;
}

std::string ObjectFields::text(std::string_view key) const {
  const auto it = object_.fields.find(key);
  return it == object_.fields.end() ? std::string() : it->second.text;
}

std::string ObjectFields::required_text(std::string_view key) const {
  std::string value = text(key);
  if (value.empty()) fail(key, "blank; it is required");
  return value;
}

double ObjectFields::coordinate(const InputField& field) const {
  const std::optional<double> value = parse_number(field.text);
  if (!value) fail_at(field.line, field.label, "'" + field.text + "' is not a number");
  if (!std::isfinite(*value))
    fail_at(field.line, field.label, "'" + field.text + "' is not finite");
  return *value;
}

double ObjectFields::number(std::string_view key, double blank_value) const {
  const auto it = object_.fields.find(key);
  if (it == object_.fields.end()) return blank_value;
  return coordinate(it->second);
}

std::vector<glm::dvec3> ObjectFields::vertices(std::size_t most) const {
  const std::vector<InputField>& coordinates = object_.coordinates;
  if (coordinates.size() % 3 != 0) {
    fail(std::to_string(coordinates.size()) +
         " vertex coordinates: the vertices are x, y, z each, so a multiple of 3");
  }
  const std::size_t count = coordinates.size() / 3;
  const auto stated = object_.fields.find("number_of_vertices");
  if (stated != object_.fields.end() && !same_text(stated->second.text, "autocalculate")) {
    // A number, as EnergyPlus reads the field (4 and 4.0 alike), that must be whole.
    const std::optional<double> n = parse_number(stated->second.text);
    if (!n || !std::isfinite(*n) || std::floor(*n) != *n) {
      fail_at(stated->second.line, stated->second.label,
              "'" + stated->second.text + "' is not a whole number (nor autocalculate)");
    }
    if (*n != static_cast<double>(count)) {
      fail_at(stated->second.line, stated->second.label,
              "says " + stated->second.text + " vertices, and " + std::to_string(count) +
                  (count == 1 ? " is" : " are") + " given");
    }
  }
  if (count < 3) {
    fail(std::to_string(count) + (count == 1 ? " vertex" : " vertices") +
         ": a surface has at least 3");
  }
  if (count > most) {
    fail(std::to_string(count) + " vertices: this object has at most " + std::to_string(most));
  }
  std::vector<glm::dvec3> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    out[i] = {coordinate(coordinates[3 * i]), coordinate(coordinates[3 * i + 1]),
              coordinate(coordinates[3 * i + 2])};
  }
  return out;
}

double ObjectFields::vertex_rounding() const {
  std::optional<int> most;
  for (const InputField& field : object_.coordinates) {
    const int d = decimals_of(coordinate(field));
    most = most ? std::max(*most, d) : d;
  }
  if (!most) return 0.0;
  return std::sqrt(3.0) / 2.0 * std::pow(10.0, -*most);
}

void ObjectFields::fail(std::string_view key, const std::string& problem) const {
  const auto it = object_.fields.find(key);
  if (it != object_.fields.end()) fail_at(it->second.line, it->second.label, problem);
  for (const FieldSpec& field : object_.spec->fields) {
    if (field.key == key) fail_at(object_.line, std::string(field.idf_name), problem);
  }
  fail(problem);
}

void ObjectFields::fail(const std::string& problem) const { fail_at(object_.line, "", problem); }

void ObjectFields::fail_at(std::size_t line, const std::string& subject,
                           const std::string& problem) const {
  std::string message;
  if (line > 0) message = "line " + std::to_string(line) + ": ";
  message += described();
  if (!subject.empty()) message += ", " + subject;
  throw InputError(file_, "", message + ": " + problem);
}

}  // namespace shadowgen::energyplus::detail
