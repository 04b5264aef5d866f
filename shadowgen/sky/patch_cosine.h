#pragma once

// The projected solid angle of a sky patch seen from a plane: ∫ max(0, cos θ) dω over the
// patch, θ the angle between a direction of the patch and the plane's unit front normal n
// (docs/sky.md, "The cosine integral"). Over the hemisphere above a horizontal plane it is
// π; the sky view factor of an unobstructed face of tilt β is (1/π) Σ over patches, which
// is (1 + cos β)/2.
//
// With d = (cos a sin φ, cos a cos φ, sin a) for altitude a and azimuth φ, dω = cos a da dφ:
// - a patch wholly in front of the plane (n·d >= 0 on it) gets the closed form
//     n_x K (cos φ0 - cos φ1) + n_y K (sin φ1 - sin φ0) + n_z Δφ (sin² a1 - sin² a0) / 2,
//   K = (a1 - a0)/2 + (sin 2a1 - sin 2a0)/4, exact up to rounding;
// - a patch wholly behind it gets 0;
// - a patch the plane cuts: for each altitude a, the integral over φ of
//   cos a max(0, n·d) is exact (the arc of φ where n·d >= 0 is found in closed form), and
//   the altitudes are integrated by the composite midpoint rule of M nodes. That integrand
//   g(a) is Lipschitz with constant Δφ (|∂(cos a n·d)/∂a| <= 1 and max(0, ·) is
//   1-Lipschitz), so the rule's error is at most Δφ Δa² / (4M); M is the least that makes
//   it at most kCutPatchTolerance × the patch's solid angle.

#include <glm/vec3.hpp>

#include "shadowgen/sky/sky_patches.h"

namespace shadowgen::sky {

// The bound, relative to the patch's solid angle, on the error of a cut patch's integral.
inline constexpr double kCutPatchTolerance = 1e-4;

// ∫ max(0, n·d) dω over `patch`, n a unit vector in east-north-up axes.
double patch_cosine_integral(const SkyPatch& patch, const glm::dvec3& normal);

}  // namespace shadowgen::sky
