#include "shadowgen/view/map_marks.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>

#include "shadowgen/model/number_text.h"

namespace shadowgen {
namespace {

// A 1/1024: the share of the distance to the target that the perspective arrow's segment
// spans, and the least foreshortening at which north is said to show.
constexpr double kNorthShare = 0x1p-10;

clipper::Point2 pixel_offset(const CameraView& view, const clipper::Point2& from,
                             const clipper::Point2& to) {
  const clipper::Point2 a = view.to_pixels(from);
  const clipper::Point2 b = view.to_pixels(to);
  return {b.x - a.x, b.y - a.y};
}

}  // namespace

std::optional<NorthArrow> north_arrow(const Scene& scene, const Camera& camera,
                                      const CameraView& view) {
  if (!scene.site) return std::nullopt;
  const double axis = scene.site->north_axis_deg * std::numbers::pi / 180.0;
  const glm::dvec3 north(-std::sin(axis), std::cos(axis), 0.0);
  const hsr::View& v = view.view();
  clipper::Point2 offset;
  double face_on = 0.0;  // the offset's length were north seen face-on
  if (v.is_perspective()) {
    const double distance = glm::length(camera.target - camera.eye);
    const double d = kNorthShare * distance;
    offset = pixel_offset(view, v.project(camera.target), v.project(camera.target + d * north));
    const double depth = glm::dot(camera.target - v.eye(), v.forward());
    const clipper::Point2 o = v.project(camera.target);
    const clipper::Point2 across = pixel_offset(view, o, {o.x + d / depth, o.y});
    face_on = std::hypot(across.x, across.y);
  } else {
    const clipper::Point2 image = v.project_offset(north);
    offset = pixel_offset(view, {0.0, 0.0}, image);
    const clipper::Point2 unit = pixel_offset(view, {0.0, 0.0}, {1.0, 0.0});
    face_on = std::hypot(unit.x, unit.y);
  }
  const double length = std::hypot(offset.x, offset.y);
  if (!(length > kNorthShare * face_on)) return std::nullopt;
  double angle = std::atan2(offset.x, -offset.y) * 180.0 / std::numbers::pi;
  if (angle < 0.0) angle += 360.0;
  if (!(angle < 360.0)) angle = 0.0;
  return NorthArrow{angle};
}

ScaleBar scale_bar(double pixels_per_unit, int width, bool metres) {
  const double longest = 0.25 * width / pixels_per_unit;
  // m × 10^k as one operation on whole numbers (10^j is exact up to j = 22), so that a
  // length prints as the round number it is.
  const auto round_length = [](double m, int k) {
    return k >= 0 ? m * std::pow(10.0, k) : m / std::pow(10.0, -k);
  };
  int k = static_cast<int>(std::floor(std::log10(longest)));
  while (round_length(1.0, k) > longest) --k;
  while (round_length(1.0, k + 1) <= longest) ++k;
  double length = round_length(1.0, k);
  for (const double m : {5.0, 2.0}) {
    if (round_length(m, k) <= longest) {
      length = round_length(m, k);
      break;
    }
  }
  std::string label;
  append_shortest(label, length);
  label += metres ? " m" : " units";
  return {length, length * pixels_per_unit, label};
}

}  // namespace shadowgen
