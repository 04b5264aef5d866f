#pragma once

// The shared vertices of one face in the indexed layout (shadowgen-shadowed/2, see
// database_format.h): every lit polygon and sun-hours region of the face is written as
// loops of indices into one table of vertices, each vertex a triple of indices into one
// table of numbers. The regions of one face share most of their vertices (its corners,
// the shadow edges between neighbouring regions), and its vertices most of their
// coordinates (a wall's vertices its plane's x or y, a roof's its height): each is
// written once.
//
// Exact: numbers are told apart by their bits (0.0 and -0.0 are two numbers), so the
// polygons read back are the ones added, bit for bit. Tables and indices come in the
// order of first use, so the same polygons added in the same order give the same text.

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

#include "hsr/polygon3.h"

namespace shadowgen::database {

// A polygon's loops, its outer loop first, then its holes: indices of vertices.
using IndexLoops = std::vector<std::vector<std::size_t>>;

class FaceVertices {
 public:
  // Adds the polygon's vertices (those not added yet) and gives its loops as indices.
  IndexLoops add(const hsr::Polygon3& polygon);

  const std::vector<double>& numbers() const { return numbers_; }
  // Per vertex, its x, y and z as indices into numbers(), one vertex after another.
  const std::vector<std::size_t>& vertices() const { return vertices_; }

 private:
  struct TripleHash {
    std::size_t operator()(const std::array<std::size_t, 3>& t) const;
  };

  std::size_t number(double value);
  std::size_t vertex(const glm::dvec3& point);

  std::vector<double> numbers_;
  std::vector<std::size_t> vertices_;
  std::unordered_map<std::uint64_t, std::size_t> number_of_bits_;
  std::unordered_map<std::array<std::size_t, 3>, std::size_t, TripleHash> vertex_of_numbers_;
};

}  // namespace shadowgen::database
