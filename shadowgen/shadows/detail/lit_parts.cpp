#include "lit_parts.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "grazing_light.h"
#include "hsr/area.h"
#include "hsr/index_groups.h"
#include "hsr/parallel.h"
#include "hsr/perimeter.h"
#include "part_failure.h"
#include "part_plane.h"

namespace shadowgen::shadows::detail {
namespace {

// Whether `lit`, the lit polygons of `part` (of area `part_area`), cover it whole as far as
// rounding can tell.
// The exact lit region lies within the part, so lit polygons whose area reaches the
// part's own are rounded outwards, and whatever they leave unlit is thinner than that
// rounding: the part is lit whole. A shortfall is taken for rounding too where both
// bounds allow it: the rounding of the lit outline, each lit vertex within `reach` of
// the exact boundary, which sweeps at most reach × its perimeter of area; and 16 u of the
// part's area (u = 2^-53), what the area's own sums round by. The first bound alone is
// far too wide where a lamp sees a large face at a grazing angle (BackProjector's reach is
// a worst case over the whole image: a wedge of shadow over 6 % of a ground would pass).
// reach is the views' lit_reach, or at least 16 u of the part's magnitude (a hot pixel of
// 12 u, clipper/clip.h, and the roundings of lifting chart points back onto the plane),
// which covers lit polygons worked out in the part's own chart (grazing light, views
// united or cut to the part).
bool lit_whole(std::span<const hsr::Polygon3> lit, const hsr::Polygon3& part, double part_area,
               double lit_reach) {
  constexpr double kUnit = 0x1p-53;
  const double shortfall = part_area - hsr::area(lit);
  if (shortfall <= 0.0) return true;
  double magnitude = 0.0;
  for (const glm::dvec3& v : part.outer) {
    magnitude = std::max({magnitude, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  }
  const double reach = std::max(lit_reach, 16.0 * kUnit * magnitude);
  double boundary = 0.0;
  for (const hsr::Polygon3& p : lit) boundary += hsr::perimeter(p);
  return shortfall <= 16.0 * kUnit * part_area && shortfall <= reach * boundary;
}

// One part's lit polygons: the views joined, cut to the part where rounding carried them
// out of it. `area`: the part's own (FaceParts::areas).
std::vector<hsr::Polygon3> joined(LitPart lit, const hsr::Polygon3& polygon,
                                  const hsr::Plane3& plane, double area) {
  std::vector<hsr::Polygon3> polygons;
  if (lit.by_view.size() == 1) {
    polygons = std::move(lit.by_view[0]);
  } else if (lit.by_view.size() > 1) {
    // Lit through several frusta of a point light: one region, not overlapping pieces.
    polygons = unite_views(lit.by_view, plane);
  }
  // A part seen almost edge-on by the light, or small and far from it: cast back onto its
  // plane, a rounded image point can land off the part. Its lit region is the part's at
  // most.
  if (!polygons.empty() && (lit.may_stray || !inside_box_of(polygons, polygon))) {
    polygons = within_part(polygons, polygon, plane);
  }
  if (!polygons.empty() && lit_whole(polygons, polygon, area, lit.lit_reach)) return {polygon};
  return polygons;
}

}  // namespace

void relight_grazed_parts(const Receivers& receivers, std::vector<LitPart>& lit,
                          LightStats& stats) {
  const std::span<const hsr::Polygon3> polygons = receivers.polygons();
  const std::span<const hsr::Plane3> planes = receivers.planes();
  const Light& light = receivers.light();
  // Receivers in parallel, each writing only its own part's list; the first that fails is
  // the one named, as in order.
  std::vector<char> grazed(receivers.size(), 0);
  hsr::for_each_in_parallel(receivers.size(), [&](std::size_t k) {
    if (!receivers.lit_side(k)) return;
    const Incidence how = incidence(polygons[k], planes[k], light);
    const std::size_t part = receivers.part(k);
    if (how == Incidence::kInPlane) lit[part].by_view.clear();
    if (how != Incidence::kGrazing) return;
    grazed[k] = 1;
    lit[part].by_view = {on_part(part, [&] {
      return lit_by_grazing_light(k, polygons, planes, receivers.coplanar(), light);
    })};
    lit[part].may_stray = false;  // worked out in the part's own plane
    lit[part].lit_reach = 0.0;
  });
  stats.faces_grazed += static_cast<std::size_t>(std::count(grazed.begin(), grazed.end(), 1));
}

std::vector<std::vector<LitPolygon>> join_per_face(const FaceParts& parts, std::vector<LitPart> lit,
                                                   LightStats& stats) {
  // Parts in parallel, then gathered by face in order.
  std::vector<std::vector<hsr::Polygon3>> joined_parts(parts.size());
  hsr::for_each_in_parallel(parts.size(), [&](std::size_t i) {
    joined_parts[i] = on_part(i, [&] {
      return joined(std::move(lit[i]), parts.polygons[i], parts.planes[i], parts.areas[i]);
    });
  });
  // A face's parts are consecutive (flatten): each face gathers its own, in parallel.
  const hsr::IndexGroups by_face = hsr::index_groups(
      parts.size(), parts.face_count, [&parts](std::size_t i) { return parts.owners[i].face; });
  std::vector<std::vector<LitPolygon>> lit_by_face(parts.face_count);
  hsr::for_each_in_parallel(parts.face_count, [&](std::size_t f) {
    for (std::size_t j = by_face.first(f); j < by_face.last(f); ++j) {
      const std::size_t i = by_face.order[j];
      for (hsr::Polygon3& p : joined_parts[i]) {
        lit_by_face[f].push_back({parts.owners[i].part, std::move(p)});
      }
    }
  });
  for (const std::vector<hsr::Polygon3>& polygons : joined_parts) {
    stats.lit_polygons += polygons.size();
  }
  return lit_by_face;
}

}  // namespace shadowgen::shadows::detail
