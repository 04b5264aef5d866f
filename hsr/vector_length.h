#pragma once

// Lengths and directions of 3D vectors whose components may have any finite magnitude.
//
// glm::length squares the components, so it overflows to inf above about 1e154 and
// underflows to 0 below about 1e-154. Coordinates in the supported range (1e-100 to 1e100,
// docs/scene-format.md) stay clear of that, but their products do not: Newell's vector
// and cross products of edges have the magnitude of an area, up to 1e200 or down to
// 1e-200, and a light's direction may be given at any scale. These functions first scale
// the vector by a power of two that brings its largest component near 1 (exact), so the
// result is correct to a few ulps wherever the answer itself is a finite double.

#include <glm/vec3.hpp>

namespace shadowgen::hsr {

// The Euclidean length of v; 0 for the zero vector.
double stable_length(const glm::dvec3& v);

// v / stable_length(v): the unit vector along v; the zero vector for the zero vector.
glm::dvec3 stable_normalize(const glm::dvec3& v);

}  // namespace shadowgen::hsr
