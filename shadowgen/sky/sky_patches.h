#pragma once

// Subdivisions of the sky hemisphere into patches (docs/sky.md, "Sky patches"):
// Tregenza's 145 patches (P. R. Tregenza, "Subdivision of the sky hemisphere for luminance
// measurements", Lighting Research and Technology 19(1), 1987) and Reinhart's MF:N
// subdivision of them (C. F. Reinhart, Daysim; as Radiance's reinhart.cal and genskyvec
// define it), of which Tregenza's is MF:1.
//
// MF:N has 7N rows of equal altitude height α = 90° / (7N + 1/2) from the horizon up, row r
// holding N × (30, 30, 24, 24, 18, 12, 6)[⌊r/N⌋] patches of equal azimuth width, then one
// zenith cap of height α/2: 144 N² + 1 patches. In each row the first patch is centred on
// true north and the patches go round clockwise seen from above (east next), as
// reinhart.cal numbers them. A patch's centre is at the middle of its altitude and azimuth
// ranges (the zenith for the cap); its solid angle, from its band limits, is exact:
// Δφ (sin a1 - sin a0), and 2π (1 - sin a0) for the cap, so that they sum to 2π.

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadowgen::sky {

// A patch of the sky: altitudes [altitude_min, altitude_max] above the horizon, azimuths
// [azimuth_min, azimuth_max] clockwise from true north, radians. azimuth_min may be
// negative (the first patch of a row straddles north); the zenith cap spans 2π.
struct SkyPatch {
  double altitude_min = 0.0, altitude_max = 0.0;
  double azimuth_min = 0.0, azimuth_max = 0.0;
  glm::dvec3 centre{0.0, 0.0, 1.0};  // unit, in east-north-up axes
  double solid_angle = 0.0;          // steradians
};

// The most Reinhart subdivisions taken (MF:64 has 589,825 patches, each a light).
inline constexpr int kMostReinhartSubdivisions = 64;

// The patches of Reinhart's MF:`subdivisions` (1: Tregenza's), rows from the horizon up,
// then the cap; std::invalid_argument unless 1 <= subdivisions <= kMostReinhartSubdivisions.
std::vector<SkyPatch> reinhart_patches(int subdivisions);

// A direction in east-north-up axes (x east, y true north, z up) in a scene's axes, whose +y
// lies `north_axis_deg` clockwise of true north (seen from above) and +z up; and back.
glm::dvec3 scene_from_sky(const glm::dvec3& east_north_up, double north_axis_deg);
glm::dvec3 sky_from_scene(const glm::dvec3& scene, double north_axis_deg);

}  // namespace shadowgen::sky
