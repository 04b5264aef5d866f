#pragma once

// Pieces of a face split by one light's lit polygons, as the partition of a face by light
// sets needs them (light_regions.h), whose pieces carry different sets: each piece is clipped
// only by the lit polygons whose boxes overlap its own, and one that no lit polygon's
// box overlaps stays whole without a clip. Under many lights (a sun path) most pieces
// of a face meet only a few of each light's lit polygons, or none.

#include <span>
#include <vector>

#include "clipper/box.h"
#include "clipper/polygon.h"

namespace shadowgen::detail {

// One light's lit polygons on a part, in its chart, with their boxes.
class LitClips {
 public:
  explicit LitClips(std::vector<clipper::PolygonWithHoles2> clips);

  bool empty() const { return clips_.empty(); }

  // Appends to `inside` the parts of `pieces` the lit polygons cover, to `outside` the
  // rest. Throws clipper::SnapRoundingError where a clip's snapping does not settle.
  void split(const clipper::PolygonSet2& pieces, clipper::PolygonSet2& inside,
             clipper::PolygonSet2& outside) const;

 private:
  std::vector<clipper::PolygonWithHoles2> clips_;
  std::vector<clipper::Box2> boxes_;
};

}  // namespace shadowgen::detail
