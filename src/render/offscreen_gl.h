// Copyright contactlaws authors.
//
// An OpenGL context with no window and no display, for MuJoCo's renderer
// (mjr_*): EGL on Mesa's surfaceless platform (EGL_MESA_platform_surfaceless),
// drawn by Mesa's software rasteriser (llvmpipe) when there is no GPU. Chosen
// over OSMesa (deprecated in Mesa, removed in Mesa 25.1) and over a hidden
// GLFW window under Xvfb (an X server to start and stop): it needs neither a
// display nor a server, and the same code uses a GPU's EGL driver where there
// is one. MuJoCo 2.2 draws through its own framebuffer object (mjFB_OFFSCREEN),
// so the context needs no surface.

#ifndef CONTACTLAWS_RENDER_OFFSCREEN_GL_H_
#define CONTACTLAWS_RENDER_OFFSCREEN_GL_H_

namespace contactlaws::render {

class OffscreenGl {
 public:
  // Creates the context and makes it current on this thread; throws Error
  // with EGL's error code when it cannot.
  OffscreenGl();
  ~OffscreenGl();
  OffscreenGl(const OffscreenGl&) = delete;
  OffscreenGl& operator=(const OffscreenGl&) = delete;

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_OFFSCREEN_GL_H_
