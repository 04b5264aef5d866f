#pragma once

// Exact tests for loops without area.

#include <glm/vec3.hpp>
#include <span>

namespace shadowgen::hsr {

// Number of distinct points, counted up to three (0, 1, 2 or 3): enough to tell a loop
// that has fewer than three distinct vertices.
int distinct_points_up_to_3(std::span<const glm::dvec3> points);

// True when all points lie on one line (fewer than three distinct points included).
// Exact: the cross product (b - a) × (c - a) is zero exactly when its three components
// are, and each component is the orient2d determinant of one coordinate projection.
// Returns at the first triple that is not collinear, so it costs O(1) on ordinary loops.
bool all_collinear(std::span<const glm::dvec3> points);

}  // namespace shadowgen::hsr
