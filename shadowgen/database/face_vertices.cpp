#include "shadowgen/database/face_vertices.h"

#include <bit>

namespace shadowgen::database {

std::size_t FaceVertices::TripleHash::operator()(const std::array<std::size_t, 3>& t) const {
  std::size_t h = t[0];
  for (int i = 1; i < 3; ++i) h = h * 0x9E3779B97F4A7C15ull + t[i];
  return h ^ (h >> 29);
}

std::size_t FaceVertices::number(double value) {
  const auto [at, added] =
      number_of_bits_.try_emplace(std::bit_cast<std::uint64_t>(value), numbers_.size());
  if (added) numbers_.push_back(value);
  return at->second;
}

std::size_t FaceVertices::vertex(const glm::dvec3& point) {
  const std::array<std::size_t, 3> triple{number(point.x), number(point.y), number(point.z)};
  const auto [at, added] = vertex_of_numbers_.try_emplace(triple, vertices_.size() / 3);
  if (added) vertices_.insert(vertices_.end(), triple.begin(), triple.end());
  return at->second;
}

IndexLoops FaceVertices::add(const hsr::Polygon3& polygon) {
  IndexLoops loops;
  loops.reserve(1 + polygon.holes.size());
  const auto add_loop = [&](const hsr::Loop3& loop) {
    std::vector<std::size_t>& indices = loops.emplace_back();
    indices.reserve(loop.size());
    for (const glm::dvec3& p : loop) indices.push_back(vertex(p));
  };
  add_loop(polygon.outer);
  for (const hsr::Loop3& hole : polygon.holes) add_loop(hole);
  return loops;
}

}  // namespace shadowgen::database
