#pragma once

// Steps 1 to 3 of render.h for any tiling of the faces: hidden-surface removal from the
// camera on the parent faces only; each visible fragment of a face seen from its front
// side split by the face's regions (clipped by each region's image but one, the inside
// going to that region, what is left to the one); each piece given its region's look and
// mapped to pixels. What the regions are and how a piece of each looks is the tiling's:
// light-set regions, shaded (render.h), or sun-hours regions, coloured by band
// (sun_hours_map.h).

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/render.h"

namespace shadowgen::view::detail {

// No region of the face: a piece seen from the face's back side, or what a fragment
// leaves where the tiling names no region to take it.
inline constexpr std::size_t kNoRegion = static_cast<std::size_t>(-1);

// Regions tiling each face, which they are made of and how a piece of each looks.
class FaceTiling {
 public:
  virtual ~FaceTiling() = default;

  // Takes face `face`'s regions; faces come in increasing order, each once.
  virtual void load(std::size_t face) = 0;
  // The face's regions: how many, and the polygons of each, on the face's parts.
  virtual std::size_t size() const = 0;
  virtual std::span<const LitPolygon> polygons(std::size_t region) const = 0;
  // The region that gets what the others leave of a fragment (not clipped itself, so the
  // pieces of a fragment cover it whatever rounding did to the regions), or kNoRegion.
  virtual std::size_t rest() const = 0;
  // Gives `piece` (face, part and back_side set) the look of region `region` of the face
  // loaded last, or of none (kNoRegion), at `centroid`, the 3D centroid of the piece, on a
  // plane of unit front normal `normal`.
  virtual void style(Piece& piece, std::size_t region, const glm::dvec3& centroid,
                     const glm::dvec3& normal) const = 0;
  // Whether the regions are layers that may overlap (render_by_light): then each visible
  // fragment is painted whole with the look of no region, and each region takes what of
  // the whole fragment lies in it, not what the others leave.
  virtual bool layered() const { return false; }
};

// The picture of `scene`'s faces split by `tiling`. Throws std::invalid_argument for a bad
// camera or size (see CameraView).
Picture paint_picture(const Scene& scene, const Camera& camera, const RenderOptions& options,
                      FaceTiling& tiling);

}  // namespace shadowgen::view::detail
