#include "detail/vertex_list.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "shadowgen/model/number_text.h"

namespace shadowgen::cityjson::detail {
namespace {

// The decimals of `value` as its shortest round-trip form writes it: "85012.345" 3,
// "1.5e-07" 8, "1200" and "1.2e+20" 0.
int decimals_written(double value) {
  const std::string text = shortest(value);
  const std::size_t exponent_at = text.find('e');
  const std::string mantissa = text.substr(0, exponent_at);
  const std::size_t point = mantissa.find('.');
  int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
  if (exponent_at != std::string::npos) {
    decimals -= static_cast<int>(parse_integer(text.substr(exponent_at + 1)).value_or(0));
  }
  return std::max(decimals, 0);
}

// Half the step of the most decimals any coordinate of `points` is written with.
double decimal_half_step(const std::vector<glm::dvec3>& points) {
  if (points.empty()) return 0.0;
  int decimals = 0;
  for (const glm::dvec3& p : points) {
    for (int axis = 0; axis < 3; ++axis) decimals = std::max(decimals, decimals_written(p[axis]));
  }
  return 0.5 * std::pow(10.0, -decimals);
}

}  // namespace

VertexTransform read_transform(const JsonValue& value) {
  JsonObject transform = value.object();
  VertexTransform out;
  const JsonValue scale = transform.get("scale");
  out.scale = scale.vec3();
  for (int axis = 0; axis < 3; ++axis) {
    if (!(out.scale[axis] > 0.0)) {
      scale.array()
          .at(static_cast<std::size_t>(axis))
          .fail(
              "a transform's scale must be above 0 (the size of one integer step of the "
              "coordinates)");
    }
  }
  out.translate = transform.get("translate").vec3();
  transform.finish();
  return out;
}

VertexList read_vertices(const JsonValue& value, const VertexTransform* transform) {
  VertexList out;
  out.points = value.vec3_list();
  if (transform == nullptr) {
    out.half_step = glm::dvec3(decimal_half_step(out.points));
    return out;
  }
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    glm::dvec3& p = out.points[i];
    p = transform->scale * p + transform->translate;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      value.array().at(i).fail("the transform takes this vertex beyond the range of a double");
    }
  }
  out.half_step = 0.5 * transform->scale;
  return out;
}

double VertexList::rounding() const { return glm::length(half_step); }

}  // namespace shadowgen::cityjson::detail
