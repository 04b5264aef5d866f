#pragma once

// Shadow volumes counted along eye rays, after Bergeron (1986), "A general version of
// Crow's shadow volumes": open models, non-planar polygons and an eye anywhere, inside
// shadow volumes included.
//
// Volumes. Every part a light takes into account as an occluder (light_scope.h: facing it
// or turned away, receivers or not) casts its own volume, one per polygon as in Bergeron's
// treatment of open models: the part itself as the near cap (its triangles,
// part_triangles.h) and, for every edge of its outer loop and its holes, a quad from the
// edge extruded away from the light (along a directional light's direction; from a point
// light through the edge's ends), far enough to pass every point that matters: the
// scene's faces and every eye ray's start. A point light's edges are first cut into
// pieces that each subtend at most 90 degrees from the light, so that the quads' far ends
// lie beyond that reach. A non-planar polygon is already split into triangle parts by the
// reader, each with its own volume (Bergeron's "L-twisted" polygons, each closed
// independently). A part that the light sees edge-on (the light in its plane) casts none:
// it shadows no interior. Each face of a volume knows its outward side: the cap's faces the
// light, a quad's away from the part's interior.
//
// Counting. The volume of part P is the set of points whose segment to the light crosses
// P; a point is in shadow when it lies in some volume. Along the eye ray from its start
// `from` to the visible point X, every crossing of a volume's face changes the count of
// volumes holding the ray's point by +1 (entering: the ray runs against the face's
// outward normal) or −1 (leaving), so
//
//     count(X) = count(from) + Σ signed crossings,
//
// where count(from), the volumes holding the eye (Bergeron's "eye in shadow"), is found
// directly: the caps the segment from `from` to the light crosses (for a perspective
// camera once per light, since every ray starts at the eye; for an orthographic one per
// ray, each starting on the plane through the eye). X is lit by the light when the count
// is zero, in shadow when it is positive.
//
// Rules and tolerances (Embree works in floats, the volumes relative to the reach's
// centre):
//   - X's own part's volume is left out, its crossings and whether it holds `from`: a
//     point of a part is never inside its own volume, the cap at the point itself.
//   - The ray stops short of X, where it is offset() off X's part toward the eye: past the
//     float rounding of X's part and of every part coplanar with it or touching it at X,
//     so that neither shadows X (coplanar parts do not shadow each other; touching does
//     not occlude). offset() is kOffsetUlps float spacings of the volumes' largest
//     |coordinate| from the centre (their far ends included); a ray at a grazing angle θ
//     to the part stops offset()/sin θ short of X along it, which moves a shadow's
//     boundary by as much at most.
//   - Crossings of one volume at the same place (within offset() along the ray: a ray
//     through an edge between two of its faces, or between two triangles of one face)
//     count once, with the sign of their sum: a ray through a volume's edge from outside
//     to inside counts +1, one grazing the edge from outside counts 0.
//   - Embree's robust mode keeps a ray from slipping between the triangles of a face.

#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/shadows/light_scope.h"

namespace shadowgen::view::detail {

// Float spacings of the volumes' largest |coordinate| an eye ray stops short of its point.
inline constexpr double kVolumeOffsetUlps = 8.0;

// An axis-aligned box in 3D.
struct Reach {
  glm::dvec3 lo{0.0}, hi{0.0};
};

class ShadowVolumes {
 public:
  // The volumes `light` casts from `parts` (every part of the scene, with their
  // hsr::plane_of and light_scope's roles, in parallel), reaching past `reach`, which must
  // hold every part and every eye ray's start. Throws std::runtime_error where Embree fails.
  ShadowVolumes(const Light& light, std::span<const hsr::Polygon3> parts,
                std::span<const hsr::Plane3> planes, std::span<const PartRole> roles,
                const Reach& reach);
  ~ShadowVolumes();
  ShadowVolumes(const ShadowVolumes&) = delete;
  ShadowVolumes& operator=(const ShadowVolumes&) = delete;

  // The parts (indices into `parts`) whose volumes hold `from`, ascending.
  std::vector<std::size_t> holding(const glm::dvec3& from) const;

  // The count of volumes, but part `part`'s, that hold `point`, a point of part `part`
  // (unit front normal `normal`), counted along the ray from `from`, where the volumes
  // `from_holding` (holding(from)) hold the ray's start. `from` must lie on `normal`'s
  // side of the part's plane.
  int count(const glm::dvec3& from, std::span<const std::size_t> from_holding,
            const glm::dvec3& point, const glm::dvec3& normal, std::size_t part) const;

  // How far short of its point an eye ray stops (the module comment).
  double offset() const;
  // The faces' triangles (caps and quads), for tests and statistics.
  std::size_t triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowgen::view::detail
