#pragma once

// Sun hours over a sun path (docs/scene-format.md, "Sun hours"): the number of a path's
// instants at which a point of a face is lit, times the minutes each stands for. The
// sun-hours regions of a face are the overlay of the instants' lit regions, each piece
// labelled with its hours; they tile the face.
//
// Method: each part of the face is taken to its exact plane chart (hsr/plane_chart.h)
// and starts as one piece lit at no instant. Each instant's lit polygons on the part split
// the pieces with the Weiler–Atherton clipper: the pieces inside count one instant more.
// Only pieces whose boxes meet both the lit region's and the shadow's are clipped (one
// clip per count); a part unlit at an instant, or lit whole (its one lit polygon the part
// itself, as generation gives it where nothing shades it), needs none. The pieces of one
// count are merged along their shared edges (clipper/merge.h) once, when the regions are
// taken. The regions are the arrangement of the instants' shadow edges: a facade that
// the shadows of a neighbour sweep across in both directions gets a grid of cells, so a
// face's regions can hold many polygons (thousands over a day at 10-minute steps). The part's own
// vertices are lifted back to themselves exactly, every other point onto the part's plane, as for
// the light-set regions (light_regions.h). So the regions' areas sum to the face's area, and Σ
// hours × area over the regions to Σ lit area × step over the instants, up to the clipper's
// rounding of crossing points (clipper/clip.h).
//
// The instants must be added in one order (the path's) for the same regions bit for bit:
// the pieces are the same sets whatever the order, but their rounded crossings are not.
// A path's instants are summed in blocks, and the blocks' sums joined (absorb) in a fixed
// tree (sun_hours_tree.h), so that shards of a path join into the very same sums.

#include <cstddef>
#include <span>
#include <vector>

#include "clipper/box.h"
#include "clipper/polygon.h"
#include "hsr/plane_chart.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

namespace shadows::detail {
class ChartRegion;
}

// One face over one sun path, an instant at a time.
class FaceSunHours {
 public:
  // The face lit at no instant yet. Parts without area get no regions.
  explicit FaceSunHours(const Face& face);

  // The sums `pieces` hold (pieces() of a FaceSunHours of the same face). Throws
  // std::invalid_argument where they do not fit the face: parts it does not have or that
  // have no area, counts not increasing, loops of fewer than three vertices or with
  // coordinates that are not finite.
  FaceSunHours(const Face& face, const SunHoursPieces& pieces);

  // Counts one more instant: lit polygons of the face at it, each on the part it names.
  // Throws clipper::SnapRoundingError where a clip's snapping does not settle.
  void add(std::span<const LitPolygon> lit);

  // Counts the instants `later` counted (sums of the same face over other instants): each
  // piece goes up by the count of the piece of `later` it lies in. Throws as add() does.
  void absorb(const FaceSunHours& later);

  // The sums as they stand, for a shard's database.
  SunHoursPieces pieces() const;

  // The regions with hours = count × step_min / 60, in increasing hours, none empty.
  std::vector<SunHoursRegion> regions(int step_min) const;

 private:
  struct CountPieces {
    std::size_t count = 0;
    clipper::PolygonSet2 pieces;
  };
  struct Part {
    std::size_t index = 0;  // in Face::parts
    hsr::Polygon3 polygon;  // the part itself
    hsr::ChartedPlane chart;
    clipper::PolygonSet2 whole;         // the part in its chart
    std::vector<CountPieces> by_count;  // increasing counts, none empty; not merged
  };

  // Splits `part`'s pieces by a region of its chart: pieces inside go one up.
  static void split_one_up(Part& part, const shadows::detail::ChartRegion& region);

  std::vector<Part> parts_;
};

// The scene's sun paths (its `sun` entries with from, to and step_min, which placed the
// lights whose Light::sun has step_min > 0), with their instants: Scene::sun_paths in
// order, those without an instant included, then any path only lights name, in the order
// of their first instant; lit_area and regions left empty.
std::vector<SunPathHours> sun_paths_of(const Scene& scene);

}  // namespace shadowgen
