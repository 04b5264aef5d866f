#pragma once

// The parts one light has to model. Its receivers are the parts that reach inside its
// range.end; the parts beyond it are left out (the spec), so a street lamp's shadows cost
// what its neighbourhood costs, except those near enough to stand between the light and
// a receiver: they occlude and receive nothing.

#include <cstddef>
#include <span>
#include <vector>

#include "closed_solids.h"
#include "face_parts.h"
#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::shadows::detail {

class Receivers {
 public:
  // Counts the faces culled by range, considered and facing away in `stats`. Parts of
  // `solids` that need not occlude this light (closed_solids.h) are left out: they are
  // turned away from it, so they get no lit area either.
  Receivers(const FaceParts& parts, const Light& light, LightStats& stats,
            const ClosedSolids* solids = nullptr);

  std::size_t size() const { return part_.size(); }
  // Receiver k's index in the FaceParts.
  std::size_t part(std::size_t k) const { return part_[k]; }
  // Whether the light reaches receiver k's front side (faces_light); false for a part
  // kept only as an occluder.
  bool lit_side(std::size_t k) const { return lit_side_[k] != 0; }

  // Per receiver, for hidden-surface removal and the light views.
  std::span<const hsr::Polygon3> polygons() const;
  std::span<const hsr::Plane3> planes() const;
  // Per receiver: its coplanar group (coplanar_groups.h), -1 for none.
  std::span<const int> coplanar() const { return coplanar_; }

  const Light& light() const { return light_; }

 private:
  const FaceParts& parts_;
  const Light& light_;
  std::vector<std::size_t> part_;
  std::vector<char> lit_side_;
  std::vector<int> coplanar_;
  // Copies of the receivers' polygons and planes, made only when some part is left out: a
  // light without range (the sun) receives on every part.
  std::vector<hsr::Polygon3> polygons_in_range_;
  std::vector<hsr::Plane3> planes_in_range_;
};

}  // namespace shadowgen::shadows::detail
