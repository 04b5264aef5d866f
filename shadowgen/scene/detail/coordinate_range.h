#pragma once

// The coordinates the readers accept (docs/scene-format.md, "Numbers").
//
// Every coordinate of a face, a light's position and a view's eye and target has a
// magnitude of at most kLargestCoordinate, and every face whose vertices are not all one
// point spans at least kSmallestExtent (the largest side of its bounding box). Inside
// that range the products that areas and planes are made of (coordinate differences
// squared, from 1e-200 to about 1e201) are normal doubles, so no area overflows to inf or
// underflows to 0; outside it a reader refuses the input rather than answer with inf,
// nan or a silent 0.

#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "hsr/polygon3.h"

namespace shadowgen::detail {

inline constexpr double kLargestCoordinate = 1e100;
inline constexpr double kSmallestExtent = 1e-100;

// What is out of range in p, or nothing.
std::optional<std::string> coordinate_problem(const glm::dvec3& p);

// What is out of range in the polygon's vertices, or nothing.
std::optional<std::string> vertex_problem(const hsr::Polygon3& polygon);

// What is out of range in a face's polygon (a coordinate, then its extent), or nothing.
std::optional<std::string> coordinate_problem(const hsr::Polygon3& polygon);

}  // namespace shadowgen::detail
