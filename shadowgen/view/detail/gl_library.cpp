#include "gl_library.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace shadowgen::view::detail {
namespace {

constexpr const char* kLibrary = "libOSMesa.so.8";

GlLibrary open_library() {
  void* handle = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw std::runtime_error(
        std::string("stencil shadows need Mesa's off-screen OpenGL (") + kLibrary +
        ", Debian's libosmesa6): " + (why != nullptr ? why : "it cannot be opened"));
  }
  // Kept open for the rest of the run: contexts may be made again at any time.
  GlLibrary library;
  const auto load = [handle](auto& function, const char* name) {
    void* symbol = dlsym(handle, name);
    if (symbol == nullptr) {
      throw std::runtime_error(std::string(kLibrary) + " has no " + name);
    }
    function = reinterpret_cast<std::remove_reference_t<decltype(function)>>(symbol);
  };
  load(library.OSMesaCreateContextExt, "OSMesaCreateContextExt");
  load(library.OSMesaDestroyContext, "OSMesaDestroyContext");
  load(library.OSMesaMakeCurrent, "OSMesaMakeCurrent");
  load(library.Clear, "glClear");
  load(library.ClearColor, "glClearColor");
  load(library.ClearDepth, "glClearDepth");
  load(library.ClearStencil, "glClearStencil");
  load(library.Color4ub, "glColor4ub");
  load(library.ColorMask, "glColorMask");
  load(library.CullFace, "glCullFace");
  load(library.DepthFunc, "glDepthFunc");
  load(library.DepthMask, "glDepthMask");
  load(library.Disable, "glDisable");
  load(library.DrawArrays, "glDrawArrays");
  load(library.Enable, "glEnable");
  load(library.EnableClientState, "glEnableClientState");
  load(library.Finish, "glFinish");
  load(library.FrontFace, "glFrontFace");
  load(library.GetError, "glGetError");
  load(library.GetIntegerv, "glGetIntegerv");
  load(library.GetString, "glGetString");
  load(library.LoadMatrixd, "glLoadMatrixd");
  load(library.MatrixMode, "glMatrixMode");
  load(library.PixelStorei, "glPixelStorei");
  load(library.PolygonOffset, "glPolygonOffset");
  load(library.ReadPixels, "glReadPixels");
  load(library.StencilFunc, "glStencilFunc");
  load(library.StencilMask, "glStencilMask");
  load(library.StencilOp, "glStencilOp");
  load(library.VertexPointer, "glVertexPointer");
  load(library.Viewport, "glViewport");
  return library;
}

}  // namespace

const GlLibrary& gl_library() {
  static std::once_flag once;
  static GlLibrary library;
  std::call_once(once, [] { library = open_library(); });
  return library;
}

}  // namespace shadowgen::view::detail
