#include "shadowgen/model/shadowed_scene.h"

#include "hsr/area.h"

namespace shadowgen {

double lit_area(std::span<const LitPolygon> lit) {
  double sum = 0.0;
  for (const LitPolygon& p : lit) sum += hsr::area(p.polygon);
  return sum;
}

std::vector<hsr::Polygon3> polygons_of(std::span<const LitPolygon> lit) {
  std::vector<hsr::Polygon3> out;
  out.reserve(lit.size());
  for (const LitPolygon& p : lit) out.push_back(p.polygon);
  return out;
}

std::vector<hsr::Polygon3> polygons_on_part(std::span<const LitPolygon> lit, std::size_t part) {
  std::vector<hsr::Polygon3> out;
  for (const LitPolygon& p : lit) {
    if (p.part == part) out.push_back(p.polygon);
  }
  return out;
}

}  // namespace shadowgen
