// Copyright contactlaws authors.

#include "render/offscreen_gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"
#include "render/render_libraries.h"

namespace contactlaws::render {
namespace {

[[noreturn]] void Fail(const char* what) {
  throw Error(fmt::format("render: no offscreen OpenGL: {} failed (EGL error 0x{:x}; Debian "
                          "packages libegl1 and libegl-mesa0)", what, Egl().GetError()));
}

}  // namespace

OffscreenGl::OffscreenGl() {
  const EglFunctions& egl = Egl();
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      egl.GetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_platform_display) Fail("eglGetPlatformDisplayEXT");
  EGLDisplay display =
      get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !egl.Initialize(display, nullptr, nullptr)) {
    Fail("eglInitialize (surfaceless platform)");
  }
  display_ = display;
  const EGLint attributes[] = {EGL_RED_SIZE,   8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8,
                               EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8,
                               EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                               // the surfaceless platform has no window configs
                               EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig config;
  EGLint count = 0;
  if (!egl.ChooseConfig(display, attributes, &config, 1, &count) || count < 1) {
    Fail("eglChooseConfig (RGBA8, depth 24, stencil 8, desktop OpenGL)");
  }
  // MuJoCo 2.2 draws with the compatibility (fixed-function) profile: the
  // default context of desktop OpenGL
  if (!egl.BindAPI(EGL_OPENGL_API)) Fail("eglBindAPI(EGL_OPENGL_API)");
  EGLContext context = egl.CreateContext(display, config, EGL_NO_CONTEXT, nullptr);
  if (context == EGL_NO_CONTEXT) Fail("eglCreateContext");
  context_ = context;
  if (!egl.MakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    Fail("eglMakeCurrent (no surface)");
  }
}

OffscreenGl::~OffscreenGl() {
  const EglFunctions& egl = Egl();
  egl.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  egl.DestroyContext(display_, context_);
  egl.Terminate(display_);
}

}  // namespace contactlaws::render
