#pragma once

// What a view must be for its picture to show anything (docs/scene-format.md, "Views";
// `render --fov`, `--scale`, `--up`): the one home of these checks for a scene's or a
// database's views, the command line's camera options and the camera itself.
//
// Field of view. A picture h pixels tall spans 2·tan(fov/2) of the eye–target distance D
// at the target, a pixel 2·tan(fov/2)/h of it. Points near the target are projected with
// a rounding of a few ε·D (ε = 2^-52), so a pixel must be many times that for the picture
// to hold anything but rounding: at the narrowest field of view, 1e-6° (1.75e-8 rad, just
// above √ε = 1.49e-8 rad), a pixel of the tallest picture `render` draws (1,000,000
// pixels) still spans 1.75e-14 D, 79 ε·D. The widest is below 180°, where tan(fov/2) is
// infinite.
//
// Orthographic scale, in pixels per scene unit. Coordinates have magnitudes up to
// kLargestCoordinate (1e100) and faces span at least kSmallestExtent (1e-100)
// (shadowgen/model/coordinate_range.h). Below 1/kLargestCoordinate pixels per unit, a
// pixel is wider than half the whole coordinate range, and every scene maps into less than
// a pixel or two; above 1/kSmallestExtent, a pixel is narrower than the smallest face the
// format describes. Both ends are refused: 1e-100 to 1e100 pixels per unit.
//
// Up. The roll of a view is fixed by cross(sight, up); where up is (nearly) parallel to
// the line of sight, that cross product is its own rounding and the roll is arbitrary.
// Up is along the sight where the sine of the angle between them is at most √ε
// (1.49e-8): the cross product of the unit vectors carries a rounding of about 3ε per
// component, so above that sine the roll is known to 3ε/sin ≤ 3√ε (4.5e-8 rad), which
// moves the edge of a picture 1,000,000 pixels wide by 0.02 pixel.

#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "shadowgen/model/coordinate_range.h"
#include "shadowgen/model/number_range.h"

namespace shadowgen {

// The most pixels along either side of a picture (`render --width`, `--height`, for the
// SVG too, so that one range serves both pictures): the widest and tallest picture libpng
// writes, its PNG_USER_WIDTH_MAX and PNG_USER_HEIGHT_MAX as it is built by default
// (shadowgen/view/png_writer.cpp checks them against the libpng compiled with). A wider
// PNG is valid, but libpng refuses to write it ("Invalid IHDR data").
inline constexpr int kLargestPictureSide = 1'000'000;

inline constexpr double kNarrowestFovDeg = 1e-6;
inline constexpr double kWidestFovDeg = 180.0;  // excluded
inline constexpr double kSmallestPixelsPerUnit = 1.0 / kLargestCoordinate;
inline constexpr double kLargestPixelsPerUnit = 1.0 / kSmallestExtent;

// A perspective view's full vertical field of view, in degrees: from kNarrowestFovDeg to
// kWidestFovDeg, kWidestFovDeg excluded.
NumberRange fov_range();

// An orthographic view's scale, in pixels per scene unit: kSmallestPixelsPerUnit to
// kLargestPixelsPerUnit (0, "fit the scene", is the camera's own and not in the range).
NumberRange scale_range();

// Whether `up` lies along `sight` (the direction from eye to target): zero, or at an
// angle whose sine is at most √ε from it, or its opposite. Both are finite; `sight` is not
// zero. Any lengths: the vectors are scaled before they are multiplied.
bool along_sight(const glm::dvec3& sight, const glm::dvec3& up);

// Nothing where `up` fixes the roll of a view along `sight`; otherwise "must not be zero"
// or "must not be parallel to the direction " + `sight_name` ("from 'eye' to 'target'").
std::optional<std::string> up_problem(const glm::dvec3& sight, const glm::dvec3& up,
                                      const std::string& sight_name);

}  // namespace shadowgen
