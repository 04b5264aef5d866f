#pragma once

// Reading an InputObject's fields as EnergyPlus reads them, every problem one InputError
// naming the file, the line (IDF), the object's class and Name and the field:
//
//   file.idf: line 14: BuildingSurface:Detailed 'Zn001:Wall001', Vertex 2 Y-coordinate:
//   '1.2.3' is not a number
//
// A blank numeric field takes the IDD's default where the caller gives one, as EnergyPlus
// does (0 where the IDD gives none).

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "detail/input_object.h"

namespace shadowgen::energyplus::detail {

class ObjectFields {
 public:
  ObjectFields(const InputObject& object, const std::string& file) : object_(object), file_(file) {}

  const InputObject& object() const { return object_; }
  const std::string& name() const { return object_.name; }
  // "BuildingSurface:Detailed 'Zn001:Wall001'" ("Version" for an unnamed object).
  std::string described() const;

  // The field's text; empty when it is blank or not given.
  std::string text(std::string_view key) const;
  // The field as a finite number; `blank_value` when it is blank.
  double number(std::string_view key, double blank_value) const;
  // The field's text, which must be given.
  std::string required_text(std::string_view key) const;

  // The vertices, x, y and z of each in turn; their count must be a multiple of 3, at
  // least 3 vertices and at most `most`, and the Number of Vertices field, unless blank
  // or autocalculate, must say how many there are.
  std::vector<glm::dvec3> vertices(std::size_t most) const;
  // How far the decimals the vertices are written with may have moved each of them:
  // with d the most decimals of any coordinate's shortest decimal form (trailing zeros
  // aside), each coordinate lies within half a unit of its last decimal, 0.5·10^-d, so a
  // vertex within √3/2·10^-d of where it was meant to be (docs/energyplus.md, "Precision").
  double vertex_rounding() const;

  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  [[noreturn]] void fail_at(std::size_t line, const std::string& subject,
                            const std::string& problem) const;
  double coordinate(const InputField& field) const;

  const InputObject& object_;
  const std::string& file_;
};

// The decimals of `value`'s shortest decimal form: 3 for 1.125, 0 for 12, -2 for 1200
// (1.2e+03), 17 for 1e-17.
int decimals_of(double value);

}  // namespace shadowgen::energyplus::detail
