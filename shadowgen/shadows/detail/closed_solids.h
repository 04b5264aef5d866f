#pragma once

// Closed solids among the scene's parts: parts whose triangles form closed surfaces,
// every edge run as often one way as the other, that touch or cross themselves nowhere
// (checked exactly: hsr/triangles_meet.h) and bound their insides outward (each shell's
// volume positive). Along any ray from a light outside such a solid, its winding number
// starts at 0, rises by one where the ray crosses one of its parts from the front and
// falls by one where it crosses one from the back, and is never negative: so the ray has
// crossed a part facing the light before any part turned away from it. A part turned away
// from the light therefore shadows nothing that the solid's parts facing the light do
// not, and need not occlude (receivers.h): on closed models, about half of the work.
//
// Decided strictly and exactly, or not at all: a part is left to occlude where anything
// is in doubt (a surface not closed, touching itself, a shell turned inside out, a part
// near edge-on to a directional light beyond what rounding can settle, a point light on
// the surface or its side not settled by any of a few rays, a surface too crowded to
// check for contacts within a budget of candidate pairs linear in its triangles). A part that
// shares its plane with others (coplanar_groups.h) may be left out too: coplanar parts do not
// shadow each other, and one facing the light keeps, where it lies, the plane's visibility it
// shared with the part turned away.

#include <cstddef>
#include <vector>

#include "face_parts.h"
#include "hsr/triangles_meet.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::shadows::detail {

class ClosedSolids {
 public:
  explicit ClosedSolids(const FaceParts& parts);

  // How many solids were found, and which part i belongs to (-1: none).
  std::size_t size() const { return solids_.size(); }
  int solid(std::size_t part) const { return solid_of_part_[part]; }

  // Per part: 1 where the part belongs to a solid that `light` lies outside of and is
  // turned away from the light, all of it strictly: it need not occlude.
  std::vector<char> need_not_occlude(const Light& light) const;

 private:
  struct Solid {
    std::vector<hsr::Triangle3> triangles;  // those with area
    glm::dvec3 low{0.0}, high{0.0};         // the box of its corners
  };
  bool outside(const Solid& solid, const glm::dvec3& point) const;

  std::vector<Solid> solids_;
  std::vector<int> solid_of_part_;
  std::vector<std::vector<hsr::Triangle3>> part_triangles_;  // of solids' parts, those with area
};

}  // namespace shadowgen::shadows::detail
