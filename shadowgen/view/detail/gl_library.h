#pragma once

// Mesa's off-screen OpenGL (libOSMesa.so.8, Debian's libosmesa6), opened the first time a
// picture needs it rather than linked: it brings LLVM, over 100 MB of mappings that every
// other run of the program would load for nothing, and that fail to map under a tight
// address-space limit (ulimit -v) before main even starts. Only what stencil_shadows.cpp
// calls is looked up.

#include <GL/gl.h>
#include <GL/osmesa.h>

namespace shadowgen::view::detail {

struct GlLibrary {
  decltype(&::OSMesaCreateContextExt) OSMesaCreateContextExt = nullptr;
  decltype(&::OSMesaDestroyContext) OSMesaDestroyContext = nullptr;
  decltype(&::OSMesaMakeCurrent) OSMesaMakeCurrent = nullptr;
  decltype(&::glClear) Clear = nullptr;
  decltype(&::glClearColor) ClearColor = nullptr;
  decltype(&::glClearDepth) ClearDepth = nullptr;
  decltype(&::glClearStencil) ClearStencil = nullptr;
  decltype(&::glColor4ub) Color4ub = nullptr;
  decltype(&::glColorMask) ColorMask = nullptr;
  decltype(&::glCullFace) CullFace = nullptr;
  decltype(&::glDepthFunc) DepthFunc = nullptr;
  decltype(&::glDepthMask) DepthMask = nullptr;
  decltype(&::glDisable) Disable = nullptr;
  decltype(&::glDrawArrays) DrawArrays = nullptr;
  decltype(&::glEnable) Enable = nullptr;
  decltype(&::glEnableClientState) EnableClientState = nullptr;
  decltype(&::glFinish) Finish = nullptr;
  decltype(&::glFrontFace) FrontFace = nullptr;
  decltype(&::glGetError) GetError = nullptr;
  decltype(&::glGetIntegerv) GetIntegerv = nullptr;
  decltype(&::glGetString) GetString = nullptr;
  decltype(&::glLoadMatrixd) LoadMatrixd = nullptr;
  decltype(&::glMatrixMode) MatrixMode = nullptr;
  decltype(&::glPixelStorei) PixelStorei = nullptr;
  decltype(&::glPolygonOffset) PolygonOffset = nullptr;
  decltype(&::glReadPixels) ReadPixels = nullptr;
  decltype(&::glStencilFunc) StencilFunc = nullptr;
  decltype(&::glStencilMask) StencilMask = nullptr;
  decltype(&::glStencilOp) StencilOp = nullptr;
  decltype(&::glVertexPointer) VertexPointer = nullptr;
  decltype(&::glViewport) Viewport = nullptr;
};

// The library's functions, opened once (thread-safe). Throws std::runtime_error naming the
// library where it cannot be opened or lacks one of them.
const GlLibrary& gl_library();

}  // namespace shadowgen::view::detail
