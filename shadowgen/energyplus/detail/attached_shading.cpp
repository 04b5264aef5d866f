#include "detail/attached_shading.h"

#include <string>

namespace shadowgen::energyplus::detail {
namespace {

// The IDD's default tilt of an overhang or fin from its opening.
constexpr double kDefaultTilt = 90.0;

// The opening's vertex 2 in its base surface's own axes (along it, up it), from the
// base's vertex 2: GetSimpleShdSurfaceData's XLLC and YLLC.
struct OnBase {
  double along, up;
};

OnBase corner_on_base(const PlacedSurface& opening, const PlacedSurface& base) {
  const glm::dvec3 p = opening.vertices[1] - base.vertices[1];
  return {-p.x * base.cos_azimuth + p.y * base.sin_azimuth,
          -p.x * base.sin_azimuth * base.cos_tilt - p.y * base.cos_azimuth * base.cos_tilt +
              p.z * base.sin_tilt};
}

bool projection(const ObjectFields& shading) {
  return shading.object().spec->name.ends_with(":Projection");
}

}  // namespace

std::optional<PlacedSurface> place_overhang(const ObjectFields& overhang,
                                            const PlacedSurface& opening,
                                            const PlacedSurface& base) {
  const double left = overhang.number("left_extension_from_window_door_width", 0.0);
  const double right = overhang.number("right_extension_from_window_door_width", 0.0);
  const double length = left + right + opening.width;
  const double depth =
      projection(overhang)
          ? overhang.number("depth_as_fraction_of_window_door_height", 0.0) * opening.height
          : overhang.number("depth", 0.0);
  if (length * depth <= 0.0) return std::nullopt;
  const double tilt =
      opening.tilt_deg + overhang.number("tilt_angle_from_window_door", kDefaultTilt);
  const OnBase corner = corner_on_base(opening, base);
  return place_on_base(
      base, opening.azimuth_deg, tilt, corner.along - left,
      corner.up + opening.height + overhang.number("height_above_window_or_door", 0.0), length,
      depth);
}

std::array<std::optional<PlacedSurface>, 2> place_fins(const ObjectFields& fin,
                                                       const PlacedSurface& opening,
                                                       const PlacedSurface& base) {
  const OnBase corner = corner_on_base(opening, base);
  std::array<std::optional<PlacedSurface>, 2> fins;
  for (int side = 0; side < 2; ++side) {
    const std::string prefix = side == 0 ? "left_" : "right_";
    const double extension = fin.number(prefix + "extension_from_window_door", 0.0);
    const double below = fin.number(prefix + "distance_below_bottom_of_window", 0.0);
    const double length =
        fin.number(prefix + "distance_above_top_of_window", 0.0) + below + opening.height;
    const double depth =
        projection(fin)
            ? fin.number(prefix + "depth_as_fraction_of_window_door_width", 0.0) * opening.width
            : fin.number(prefix + "depth", 0.0);
    if (length * depth <= 0.0) continue;
    // Both fins turn the same way from the opening's azimuth: 90 degrees by default, so
    // that they stand out of the base surface's plane (GetSimpleShdSurfaceData).
    const double azimuth =
        opening.azimuth_deg -
        (180.0 - fin.number(prefix + "tilt_angle_from_window_door", kDefaultTilt));
    const double along =
        side == 0 ? corner.along - extension : corner.along + opening.width + extension;
    fins[side] =
        place_on_base(base, azimuth, opening.tilt_deg, along, corner.up - below, -depth, length);
  }
  return fins;
}

}  // namespace shadowgen::energyplus::detail
