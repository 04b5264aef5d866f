#pragma once

// Checks of the supported coordinate range (shadowgen/model/coordinate_range.h) on what
// the readers read.

#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "hsr/polygon3.h"
#include "shadowgen/model/coordinate_range.h"

namespace shadowgen::scene::detail {

// What is out of range in p, or nothing.
std::optional<std::string> coordinate_problem(const glm::dvec3& p);

// What is out of range in the polygon's vertices, or nothing.
std::optional<std::string> vertex_problem(const hsr::Polygon3& polygon);

// What is out of range in a face's polygon (a coordinate, then its extent), or nothing.
std::optional<std::string> coordinate_problem(const hsr::Polygon3& polygon);

}  // namespace shadowgen::scene::detail
