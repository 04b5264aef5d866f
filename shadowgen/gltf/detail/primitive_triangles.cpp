#include "detail/primitive_triangles.h"

namespace shadowgen::gltf::detail {

std::optional<Topology> triangle_topology(int mode) {
  switch (mode) {
    case -1:
    case 4:
      return Topology::kTriangles;
    case 5:
      return Topology::kTriangleStrip;
    case 6:
      return Topology::kTriangleFan;
    default:
      return std::nullopt;
  }
}

const char* mode_name(int mode) {
  switch (mode) {
    case 0:
      return "POINTS";
    case 1:
      return "LINES";
    case 2:
      return "LINE_LOOP";
    case 3:
      return "LINE_STRIP";
    case 4:
      return "TRIANGLES";
    case 5:
      return "TRIANGLE_STRIP";
    case 6:
      return "TRIANGLE_FAN";
    default:
      return "unknown";
  }
}

std::size_t triangle_count(Topology topology, std::size_t vertices) {
  if (topology == Topology::kTriangles) return vertices / 3;
  return vertices < 3 ? 0 : vertices - 2;
}

std::array<std::size_t, 3> triangle_corners(Topology topology, std::size_t i) {
  switch (topology) {
    case Topology::kTriangles:
      return {3 * i, 3 * i + 1, 3 * i + 2};
    case Topology::kTriangleStrip:
      return {i, i + 1 + i % 2, i + 2 - i % 2};
    case Topology::kTriangleFan:
      return {i + 1, i + 2, 0};
  }
  return {0, 0, 0};
}

}  // namespace shadowgen::gltf::detail
