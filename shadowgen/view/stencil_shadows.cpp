#include "shadowgen/view/stencil_shadows.h"

#include <GL/osmesa.h>
// osmesa.h brings GL/gl.h, which brings GL/glext.h (GL_INCR_WRAP, GL 1.4).
#include <GL/gl.h>

#include <algorithm>
#include <cstdio>
#include <glm/vec4.hpp>
#include <stdexcept>
#include <string>

#include "detail/gl_library.h"
#include "detail/stencil_parts.h"
#include "detail/stencil_plan.h"

namespace shadowgen {
namespace {

const view::detail::GlLibrary& gl() { return view::detail::gl_library(); }

using glm::dvec3;
using glm::dvec4;
static_assert(sizeof(dvec4) == 4 * sizeof(double), "vertex arrays of dvec4 as GL_DOUBLE × 4");

// The volumes' push away from the eye: slope factor and units of the depth buffer's step.
constexpr float kOffsetFactor = 0.5f;
constexpr float kOffsetUnits = 4.0f;

// ---- OSMesa ----------------------------------------------------------------------------

class OffscreenContext {
 public:
  OffscreenContext(int width, int height) : buffer_(static_cast<std::size_t>(width) * height * 4) {
    context_ = gl().OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (context_ == nullptr) throw std::runtime_error("OSMesa could not create a GL context");
    if (!gl().OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
      gl().OSMesaDestroyContext(context_);
      throw std::runtime_error("OSMesa could not make its GL context current");
    }
  }
  ~OffscreenContext() {
    gl().OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    gl().OSMesaDestroyContext(context_);
  }
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

void require_capabilities() {
  GLint depth = 0, stencil = 0;
  gl().GetIntegerv(GL_DEPTH_BITS, &depth);
  gl().GetIntegerv(GL_STENCIL_BITS, &stencil);
  const char* version = reinterpret_cast<const char*>(gl().GetString(GL_VERSION));
  int major = 0, minor = 0;
  if (version == nullptr || std::sscanf(version, "%d.%d", &major, &minor) != 2) major = 0;
  if (depth < 24 || stencil < 8 || major * 10 + minor < 14) {
    throw std::runtime_error(
        "OSMesa's context lacks 24 depth bits, 8 stencil bits or GL 1.4 (got " +
        std::to_string(depth) + ", " + std::to_string(stencil) + ", " +
        (version ? version : "no version") + ")");
  }
}

void draw(const std::vector<dvec4>& vertices) {
  if (vertices.empty()) return;
  gl().VertexPointer(4, GL_DOUBLE, 0, vertices.data());
  gl().DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
}

}  // namespace

StencilGlCamera stencil_gl_camera(const Scene& scene, const Light& light, const CameraView& view,
                                  const StencilOptions& options) {
  return view::detail::make_stencil_plan(scene, light, view, options).camera;
}

std::vector<StencilEdge> stencil_silhouette_edges(const Scene& scene, const Light& light) {
  const std::vector<view::detail::StencilPart> parts = view::detail::stencil_parts(scene, light);
  const view::detail::SilhouetteMarks marks = view::detail::silhouette_marks(scene, light);
  std::vector<StencilEdge> edges;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (!view::detail::builds_volume(parts[p], &marks)) continue;
    view::detail::for_each_side_edge(parts[p], &marks[p], [&](const dvec3& a, const dvec3& b) {
      edges.push_back({a, b});
    });
  }
  return edges;
}

StencilResult stencil_lit_mask(const Scene& scene, const Light& light, const CameraView& view,
                               const StencilOptions& options) {
  const view::detail::StencilPlan plan =
      view::detail::make_stencil_plan(scene, light, view, options);
  const int w = view.width(), h = view.height();
  StencilResult result;
  result.width = w;
  result.height = h;
  result.zfail_used = plan.zfail;
  result.lit.assign(static_cast<std::size_t>(w) * h, 0);

  OffscreenContext context(w, h);
  require_capabilities();
  gl().Viewport(0, 0, w, h);
  gl().MatrixMode(GL_PROJECTION);
  gl().LoadMatrixd(plan.camera.projection.data());
  gl().MatrixMode(GL_MODELVIEW);
  gl().LoadMatrixd(plan.camera.modelview.data());
  gl().Disable(GL_LIGHTING);
  gl().Disable(GL_DITHER);
  gl().Disable(GL_CULL_FACE);
  gl().FrontFace(plan.camera.front_ccw ? GL_CCW : GL_CW);
  gl().EnableClientState(GL_VERTEX_ARRAY);

  // 1. The depth pass; red marks the parts facing the light.
  gl().ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl().ClearDepth(1.0);
  gl().ClearStencil(0);
  gl().Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  gl().Enable(GL_DEPTH_TEST);
  gl().DepthFunc(GL_LESS);
  gl().DepthMask(GL_TRUE);
  gl().Color4ub(255, 0, 0, 255);
  draw(plan.facing);
  gl().Color4ub(0, 0, 0, 255);
  draw(plan.other);

  // 2. The volumes into the stencil buffer: no depth or colour writes.
  gl().ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl().DepthMask(GL_FALSE);
  gl().Enable(GL_STENCIL_TEST);
  gl().StencilFunc(GL_ALWAYS, 0, 0xff);
  gl().StencilMask(0xff);
  gl().Enable(GL_POLYGON_OFFSET_FILL);
  gl().PolygonOffset(kOffsetFactor, kOffsetUnits);
  gl().Enable(GL_CULL_FACE);
  if (plan.zfail) {
    gl().CullFace(GL_FRONT);
    gl().StencilOp(GL_KEEP, GL_INCR_WRAP, GL_KEEP);  // back faces behind the surface: +1
    draw(plan.sides);
    draw(plan.caps);
    gl().CullFace(GL_BACK);
    gl().StencilOp(GL_KEEP, GL_DECR_WRAP, GL_KEEP);  // front faces behind the surface: −1
    draw(plan.sides);
    draw(plan.caps);
  } else {
    gl().CullFace(GL_BACK);
    gl().StencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);  // front faces before the surface: +1
    draw(plan.sides);
    gl().CullFace(GL_FRONT);
    gl().StencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);  // back faces before the surface: −1
    draw(plan.sides);
  }
  gl().Finish();
  if (gl().GetError() != GL_NO_ERROR) throw std::runtime_error("OpenGL reported an error");

  // 3. Read back (GL's row 0 is the bottom).
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::vector<GLubyte> stencil(n), colour(4 * n);
  std::vector<GLfloat> depth(n);
  gl().PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl().ReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
  gl().ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, colour.data());
  gl().ReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t gl = static_cast<std::size_t>(h - 1 - y) * w + x;
      const bool lit = stencil[gl] == 0 && depth[gl] < 1.0f && colour[4 * gl] == 255;
      result.lit[static_cast<std::size_t>(y) * w + x] = lit ? 1 : 0;
    }
  }
  return result;
}

}  // namespace shadowgen
