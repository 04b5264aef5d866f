#include "light_view_pass.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "back_projector.h"
#include "clipper/merge.h"
#include "coplanar_receivers.h"
#include "hsr/hidden_surface.h"
#include "hsr/index_groups.h"
#include "hsr/parallel.h"
#include "part_failure.h"
#include "part_plane.h"

namespace shadowgen::shadows::detail {
namespace {

// Stage 1: the fragments the view sees, per receiver, in image coordinates.
std::vector<clipper::PolygonSet2> seen_by_view(const Receivers& receivers, const hsr::View& view,
                                               const hsr::HsrOptions& hsr, LightStats& stats) {
  hsr::VisibleSurfaces visible;
  try {
    visible = hsr::remove_hidden_surfaces(receivers.polygons(), receivers.planes(), view, hsr);
  } catch (const hsr::PolygonClipError& e) {
    throw PartFailure(receivers.part(e.polygon()), e.problem());
  }
  stats.fragments += visible.fragments.size();
  // Each receiver gathers its own fragments, in their order, in parallel.
  std::vector<hsr::Fragment>& fragments = visible.fragments;
  const hsr::IndexGroups by_receiver =
      hsr::index_groups(fragments.size(), receivers.size(),
                        [&fragments](std::size_t i) { return fragments[i].parent; });
  std::vector<clipper::PolygonSet2> seen(receivers.size());
  hsr::for_each_in_parallel(receivers.size(), [&](std::size_t k) {
    for (std::size_t j = by_receiver.first(k); j < by_receiver.last(k); ++j) {
      seen[k].push_back(std::move(fragments[by_receiver.order[j]].shape));
    }
  });
  return seen;
}

// Stage 3: receiver k's lit pieces in the image, merged and cast back onto its plane, as
// one more view of its part.
void cast_back(const Receivers& receivers, std::size_t k, const hsr::View& view,
               const clipper::PolygonSet2& lit, LitPart& part) {
  const hsr::Polygon3& polygon = receivers.polygons()[k];
  const BackProjector back(view, polygon, receivers.planes()[k]);
  // Half the reach leaves the other half to the roundings the join and the database add.
  if (back.cast_reach() > 0.5 * part_reach(polygon)) part.may_stray = true;
  const clipper::PolygonSet2 merged =
      on_part(receivers.part(k), [&] { return clipper::merge_adjacent(lit); });
  // The rounding of the lit points cast back (lit_parts.h, LitPart::lit_reach).
  double image = 0.0;
  const auto magnitude_of = [&image](const clipper::Loop2& loop) {
    for (const clipper::Point2& q : loop) image = std::max({image, std::abs(q.x), std::abs(q.y)});
  };
  for (const clipper::PolygonWithHoles2& p : merged) {
    magnitude_of(p.outer);
    for (const clipper::Loop2& hole : p.holes) magnitude_of(hole);
  }
  part.lit_reach = std::max(part.lit_reach, back.reach_of(image));
  std::vector<hsr::Polygon3> polygons;
  for (const clipper::PolygonWithHoles2& p : merged) {
    hsr::Polygon3 detail = back.lift(p);
    if (detail.outer.size() >= 3) polygons.push_back(std::move(detail));
  }
  part.by_view.push_back(std::move(polygons));
}

}  // namespace

void light_through_view(const Receivers& receivers, const hsr::View& view,
                        const hsr::HsrOptions& hsr, std::vector<LitPart>& lit, LightStats& stats) {
  std::vector<clipper::PolygonSet2> seen = seen_by_view(receivers, view, hsr, stats);
  std::vector<clipper::PolygonSet2> extra = seen_on_shared_planes(receivers, view, seen);
  // Receivers in parallel: each writes only its own part's list.
  hsr::for_each_in_parallel(receivers.size(), [&](std::size_t k) {
    if (!receivers.lit_side(k) || (seen[k].empty() && extra[k].empty())) return;
    clipper::PolygonSet2 pieces = std::move(seen[k]);
    for (auto& q : extra[k]) pieces.push_back(std::move(q));
    // Every view that saw the part gets its list, empty or not, for the join
    // (lit_parts.h) to see.
    cast_back(receivers, k, view, pieces, lit[receivers.part(k)]);
  });
}

}  // namespace shadowgen::shadows::detail
