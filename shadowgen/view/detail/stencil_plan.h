#pragma once

// What the GL passes of stencil shadow volumes draw (shadowgen/view/stencil_shadows.h),
// computed in doubles: the camera as GL matrices, the depth pass's triangles and the
// volumes' sides and caps, and whether z-fail is needed.

#include <glm/vec4.hpp>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/stencil_shadows.h"
#include "stencil_parts.h"

namespace shadowgen::view::detail {

// Everything the GL passes draw: the camera and the volumes' triangles, as homogeneous
// vertices relative to the camera's origin.
struct StencilPlan {
  StencilGlCamera camera;
  std::vector<StencilPart> parts;
  std::vector<glm::dvec4> facing, other;  // the depth pass: parts facing the light, the rest
  std::vector<glm::dvec4> sides, caps;    // the volumes
  bool zfail = false;
};

// The plan for `light` seen through `view`: throws std::invalid_argument for a directional
// light whose direction is zero or not finite.
StencilPlan make_stencil_plan(const Scene& scene, const Light& light, const CameraView& view,
                              const StencilOptions& options);

}  // namespace shadowgen::view::detail
